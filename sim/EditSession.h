#pragma once

#include "FoldPlan.h"
#include "FoldWatch.h"
#include "Simulation.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <numbers>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace pf {

// One mutating call on an EditSession, stamped with the step it was applied before.
struct EditCommand {
    // Diverged: a step failed here (the editor pauses; the state was rolled back, but the
    // tool had moved and the integrator restarts), so a replay makes the same attempt.
    enum class Kind : std::uint8_t {
        Tool = 1,
        PlaceTool = 2,
        Undo = 3,
        Redo = 4,
        Params = 5,
        Diverged = 6,
        Settle = 7,
        Grab = 8,
        Pin = 9,
        Reset = 10,
        Fold = 11
    };
    Kind kind = Kind::Tool;
    std::int64_t step = 0;
    Vec3 target = Vec3::Zero();              // Tool, Grab, Pin
    double radius = 0.0;                     // Tool, Pin
    bool visible = false;                    // Tool; for a Grab, it begins (picks a vertex up)
    bool pressed = false;                    // Tool; for a Grab, it is held
    int stroke = -1;                         // Undo, Redo
    std::shared_ptr<const SimParams> params; // Params (shared: most commands are tool moves)
    std::shared_ptr<const World> world;      // Reset: the sheet it starts again from
    std::shared_ptr<const FoldRequest> fold; // Fold (shared, as params are)

    // A command of `kind` with nothing else set; the step is stamped when recorded.
    static EditCommand of(Kind kind) {
        EditCommand c;
        c.kind = kind;
        return c;
    }
};

// Everything needed to do a session again: the world it started from, the tool's target
// and button then, every command, and the step it ended at.
struct EditLog {
    World start;
    Vec3 toolTarget = Vec3::Zero();
    bool pressed = false;
    std::vector<EditCommand> commands;
    std::int64_t endStep = 0;
    // stateHash of the sheet at endStep, as the session that recorded it had it. A replay
    // that ends elsewhere says so: a recording made by another version may replay
    // differently (its undo and redo, say), and without this it did so silently.
    // Recordings made before it have none.
    std::optional<std::uint64_t> endState;
};

// What a user does to a sheet, applied between steps: the tool follows a target at a
// bounded speed, a press of it is a stroke, and a stroke's damage (breaks and hinges)
// is undone through §4.2 recovery and done again. Plain C++, so the editor's
// simulation thread and anything headless drive the same code.
class EditSession {
  public:
    explicit EditSession(World world);
    // Ready to replay `log`: its start world, tool target and button.
    explicit EditSession(const EditLog& log);

    // The tool follows its target no faster than this: a jump of the cursor across the
    // sheet must not teleport the tool through the paper.
    static constexpr double kMaxToolSpeed = 1.5; // m/s
    // A hand that holds paper (a grab) moves it no faster than this. At the tool's speed a
    // wheel notch (1 cm toward the eye) jerked a sheet lying on the desk by its corner,
    // and the sheet slid on past the hand and buckled against it: three notches made a
    // break and three hinges; at this speed, none.
    static constexpr double kMaxHandSpeed = 0.5; // m/s

    Simulation& simulation() { return sim_; }
    const Simulation& simulation() const { return sim_; }
    const World& world() const { return sim_.world(); }

    // A new sheet: the tool keeps its size and visibility, the stroke history is cleared.
    void replaceWorld(const World& world);
    // A different paper weighs differently: the masses follow its areal density. σ is
    // kept as the world has it: it is a look, which the editor holds and saves itself.
    void setParams(const SimParams& params);

    // What an undo step is, for its name in the history.
    enum class StrokeKind : std::uint8_t { Push, Grab, Pin, Unpin, Settle, Reset, Fold };
    struct StrokeEnd {
        int stroke = 0; // its index, for undoStroke / redoStroke
        int events = 0; // breaks and hinges it made; for a pin, the vertices it (un)pinned
        StrokeKind kind = StrokeKind::Push;
    };
    // Moves the tool's target; a release ends the stroke, which is returned when it
    // changed the sheet (broke or hinged something, or moved it by more than
    // kStrokeMoves); a stroke that changed nothing has nothing to undo.
    std::optional<StrokeEnd> setTool(const Vec3& target, double radius, bool visible, bool pressed);
    static constexpr double kStrokeMoves = 1e-4; // m
    // Strokes further back than this are undone by recovery alone, without their sheet
    // states (two copies of every vertex's position and velocity per stroke).
    static constexpr std::size_t kStrokesWithLook = 100;
    // Each redo logs its breaks again: past this many damage events (the sheet file's
    // limit) a redo is refused, so that undo/redo cannot grow the log without bound.
    static constexpr std::size_t kMaxDamageEvents = 8'000'000;

    // Grab: `begin` picks up the free vertex nearest to `target`; while `held` it
    // follows `target` (no faster than kMaxHandSpeed, never below the ground), pinned for
    // the solver, so the sheet hangs from it; on release it is let go with its velocity
    // and falls. A grab is a stroke like a push. Refused while the push tool is pressed;
    // a pinned vertex is not grabbed (the pin holds).
    std::optional<StrokeEnd> grab(const Vec3& target, bool held, bool begin);
    bool grabbing() const { return grabbed_ != kNone; }
    // The world as a file should keep it: a grabbed vertex is held, not pinned.
    World worldToSave() const;
    Index grabbedVertex() const { return grabbed_; }
    // How far the paper the hand holds is from where the hand pulls it (m) while pins hold
    // the paper too; 0 when nothing is held or no pin holds the paper. Paper pulled taut
    // between pins does not stretch to follow, and the hand pulls with at most
    // kHandForce (a pinch the paper would slip from): a user dragging on saw the paper
    // stay where it was and took the Grab tool for broken.
    double grabHeldBack() const;
    // Pin: toggles the vertices around `point` — when the click is on free paper (see
    // kOnPinShare), the free vertices within `radius` of the point are pinned; when it is
    // on a pin, that pin is freed: the vertices the click that set it pinned, or, for a
    // pin this session did not set, the pin's patch (pinned vertices joined by springs,
    // within kPinPatchReach radii of the point). Pinned vertices stand still and are saved
    // with the sheet. An undo step; nothing when no vertex is that close.
    std::optional<StrokeEnd> pin(const Vec3& point, double radius);
    static constexpr double kPinPatchReach = 3.0;
    // A click this share of the radius from a pin frees it; farther off, it frees the
    // pin only if no free paper lies at less than half the pin's distance.
    static constexpr double kOnPinShare = 0.25;

    // Reset: the sheet starts again from `world` (the scene as New makes it) as an undo
    // step, unlike New and Open: undo gives back the sheet as it was, with the strokes
    // made on it, and redo the fresh sheet as the next edit found it (or as it was when
    // the Reset was undone, if no step came after it). The clock runs on (commands stay
    // in step order) and the tool stays where it is. A grab is let go; refused while the
    // push tool is pressed.
    std::optional<StrokeEnd> reset(const World& world);

    // Fold (FoldPlan.h): the flap is pinned and carried round the line, held, and let go;
    // the step that lets it go ends the fold as an undo step (takeFinished). Refused, with
    // the reason, on a request planFold refuses; refused (Busy) while the push tool is
    // pressed, a grab is held or another fold is under way. While a fold is under way
    // the other edits wait: pressing the tool, grabbing, pinning, undo, redo, Reset and
    // Settle do nothing.
    FoldRefusal fold(const FoldRequest& request);
    bool folding() const { return foldGroup_ != kNoFold; }
    // A second after a fold was let go (FoldWatch::kSeconds), how far its flap had turned
    // back, in degrees (negative: further closed), once; nothing if another edit came
    // first. A flap that turned back more than kSprangBack did not keep its crease.
    std::optional<double> takeFoldTurnedBack();
    static constexpr double kSprangBack = 45.0; // degrees
    // Within that second: true once, when the flap has turned back past kSprangBack
    // (FoldWatch::openingEarly), so that "Folded." does not stand over an open sheet.
    bool takeFoldOpening() { return std::exchange(foldOpening_, false); }
    // At the same time, the share of the paper on the flap's side that the carry did not
    // hold and that lies unfolded (FoldWatch::Reading::unfolded), once, if some does;
    // kLeftBehindShare of it is a fold that left part of the paper behind.
    std::optional<double> takeFoldLeftBehind();
    // (Mountain folds of a twice-folded stack, whose left-out layers went round, read
    // 0-4 %; folds that left layers lying, 25-41 %.)
    static constexpr double kLeftBehindShare = 0.1;
    // What a user is told of the fold a second after its let-go, from those two readings
    // and the angle asked (degrees): that it opened again (and how far, at most all of
    // the angle asked: a 60° fold read 61° back), else that it closed more than
    // kSprangBack past the angle asked: fell shut if it lies within kShutWithin of flat
    // (a 90° fold closed flat under "Folded."; "94° further than asked" read as past
    // flat), else how far it closed (a card folded to 60° stood at 124°, "fell shut"),
    // else that it left part of the paper behind (and how much), else nothing.
    struct FoldNotice {
        enum class Kind : std::uint8_t {
            SprangBack,
            FellShut,
            ClosedFurther,
            LeftPaperBehind
        } kind;
        // Degrees turned back; the angle asked (fell shut); degrees closed further; or the
        // share of the flap's side left behind.
        double value;
    };
    static constexpr double kShutWithin = 15.0; // degrees
    static std::optional<FoldNotice> foldNotice(std::optional<double> turnedBack,
                                                std::optional<double> leftBehind,
                                                double askedDegrees);
    // The angle the last fold was asked for, degrees (180 for one resumed from a file,
    // whose angle is not known).
    double foldAskedDegrees() const { return foldAngle_ * 180.0 / std::numbers::pi; }

    // Undo recovers (§4.2), newest first, every break and hinge since the stroke began —
    // its own and those the sheet made settling after it — and, when all came back, gives
    // back the sheet as it was when the stroke began: positions, velocities, plastic folds.
    // Redo does the damage again and gives back the sheet as it was when the stroke was
    // undone (an undo of the newest step done ends its settling); the damage the sheet
    // made since an undo is taken back by the next redo, and what a step under a waiting
    // redo took of it (Stroke::sinceLaterUndo) by that redo.
    // Returns the number of damage events recovered (or done again); nothing for an
    // unknown stroke, or one refused: an undo of a step not done, a redo of one done, a
    // redo onto a mesh other than the one the step began on.
    std::optional<int> undoStroke(int stroke);
    std::optional<int> redoStroke(int stroke);

    // Steps `steps` times, moving the tool toward its target first in each. Stops at the
    // first step that is not Ok and returns its status.
    StepStatus advance(int steps);
    // While paused the tool still goes where the user points, without a step. True if it
    // moved.
    bool placeToolAtTarget();

    // The artist's "keep it like this". The sheet steps on without breaking or hinging
    // until it comes to rest (every vertex slower than kRestSpeed) or kSettleSeconds have
    // passed; then it stands frozen — the clock runs, nothing moves — until the next
    // edit (a press of the tool, undo, redo, new parameters, a new sheet). Once frozen
    // it is an undo step like a stroke (takeFinished): undo gives back the sheet as it was
    // when Settle was chosen, redo the settled sheet, frozen again.
    void settle();
    static constexpr double kRestSpeed = 1e-3;    // m/s
    static constexpr double kSettleSeconds = 3.0; // s
    // The undo step of a settle that froze the sheet, or of a fold that was let go, since
    // the last call, once.
    std::optional<StrokeEnd> takeFinished();
    // The steps whose breaks and hinges changed since the last call, with their new count
    // (StrokeEnd::events), once each: a push or grab takes what the sheet breaks settling
    // after it when the next edit begins, and gives back what a later step's redo takes
    // back. The History named each with its count at the release only.
    std::vector<StrokeEnd> takeRecounted();
    bool settling() const { return settle_ == Settle::Settling; }
    bool frozen() const { return settle_ == Settle::Frozen; }

    // The session since it began or since the last replaceWorld, up to now.
    EditLog log() const;

    // Applies one command, as the call it stands for.
    void apply(const EditCommand& command);

  private:
    // What a stroke did, enough to undo it and do it again.
    struct StrokeEvent {
        Index event = kNone;
        EventKind kind = EventKind::Break;
        Index edge = kNone;
        double hingeRest = 0.0;
        double creaseRest = 0.0; // a break's crease: the length it broke at
        // When it was made: a redo stamps it so, or the sheet's breaks in the last second
        // (the editor's break rate) read every redone break as new (78 a second after a
        // fold's redo, in a user's session).
        std::int64_t step = 0;
    };
    // What the user saw: the sheet's motion state (its topology is the events' job).
    struct SheetLook {
        std::vector<Vec3> x, v;
        PaperState paper;
        // The scene's scripted pins and the clock then: where the script's motions stood.
        std::vector<PinGroup> scriptPins;
        double time = 0.0;
    };
    // Moves a script's times by `shift` seconds (its motions happen that much later).
    static void shiftScript(std::vector<PinGroup>& pins, double shift);
    struct MeshSize {
        Index vertices = 0, springs = 0, triangles = 0;
        bool operator==(const MeshSize&) const = default;
    };
    MeshSize meshSize() const;
    struct Stroke {
        Index firstEvent = 0; // the damage log's length when it began (or was redone)
        MeshSize pressedOn;   // redo only onto the mesh the stroke began on
        std::vector<StrokeEvent> events;
        SheetLook before, after;
        // The damage log's length when it ended, and whether it is done (not undone):
        // what the sheet breaks settling after it, until the next edit, is its own too.
        Index endEvent = 0;
        bool applied = true;
        // Where in `events` the damage begins that the sheet made after a later step was
        // undone, while that step waits for its redo: a redo of this step gives it back
        // (the sheet as the user saw it), and the later step's redo takes it back first.
        std::optional<std::size_t> sinceLaterUndo;
        StrokeKind kind = StrokeKind::Push;
        bool settle = false;       // a Settle: redo freezes the sheet again
        bool frozenBefore = false; // began on a settled sheet: undo freezes it again
        // A pin: these vertices were set to `pinnedTo` (undo sets them back).
        std::vector<Index> pinChanged;
        bool pinnedTo = false;
        // The sheet it was made on (sheet_): its edge and vertex ids mean nothing on
        // another, so undo and redo need that sheet.
        int sheet = 0;
        // A Reset: the whole sheet before it (as the last do left it) and after it (as
        // the next edit found it, or its undo as the newest step, through
        // keepSettlingWithLastStroke, or through resetSeenAt_ while a redo waited), and
        // which sheet each is.
        std::shared_ptr<const World> worldBefore, worldAfter;
        int sheetBefore = 0, sheetAfter = 0;
    };
    SheetLook look() const;
    // Gives back `look` if the sheet has the same vertices again; false otherwise.
    bool restore(const SheetLook& look);
    std::optional<StrokeEnd> endStroke(StrokeKind kind);
    // Adds the active damage events from `from` up to `to` to `stroke`, with their rest
    // lengths.
    void appendEvents(Stroke& stroke, Index from, Index to) const;
    // The newest step that is done (later ones were undone, and are gone once an edit
    // begins); null if none is.
    Stroke* newestApplied();
    // The newest step done if it is a Reset to the sheet in place; null otherwise.
    Stroke* newestReset();
    // When the next edit begins: the damage the sheet made settling since the newest
    // stroke ended, and the sheet as it is now, become that stroke's, so that its redo
    // gives back the sheet the next edit began on (whose redo needs that mesh).
    // `forALaterRedo`: an undone step after it waits for its redo, which needs the mesh
    // without this damage (Stroke::sinceLaterUndo). A Reset's step keeps no damage log
    // of its own: its worldAfter becomes the whole world as it is now (without the hand's
    // pin), and with `forALaterRedo` nothing changes.
    void keepSettlingWithLastStroke(bool forALaterRedo = false);
    // The same with the damage log up to `until` and the sheet as `then` shows it.
    void keepSettlingWithLastStroke(Index until, SheetLook then, bool forALaterRedo = false);
    // An undone step of this sheet may wait for its redo: it lies after the newest step
    // that is done (the editor's History offers its redo until the next step is made;
    // this also sees steps the History dropped behind an undone Reset, which then only
    // keep damage apart that nothing takes back). Its redo needs the mesh it began on, so
    // no stroke before it may take the damage since as its own. (A Reset's redo needs no
    // mesh.)
    bool redoWaiting() const;
    // Fills in `stroke`'s start (from beginStroke) and its sheet before and after.
    void closeStroke(Stroke& stroke);
    // The way from `from` toward `to` that one step allows at `speed`.
    Vec3 boundedMove(const Vec3& from, const Vec3& to, double speed = kMaxToolSpeed) const;
    // Lets a grabbed vertex go; no undo step.
    void releaseGrab();
    void setPins(const std::vector<Index>& vertices, bool pinned);
    // Moves a grabbed vertex toward the grab's target for the coming step.
    void pullGrabbed();
    // Adds an undo step; the oldest steps beyond kStrokesWithLook drop their looks.
    StrokeEnd keepStroke(Stroke stroke, StrokeKind kind);
    // The done Pin step that last set `vertex` pinned, if no later done step freed it.
    const Stroke* pinThatHeld(Index vertex) const;
    void beginLog();
    void record(EditCommand command);
    // Puts `world` in place as sheet `sheet`, keeping the clock and the tool; a grab is
    // let go and a settle ends.
    void swapSheet(const World& world, int sheet);

    Simulation sim_;
    Vec3 toolTarget_ = Vec3::Zero();
    bool pressed_ = false;
    Index grabbed_ = kNone;
    Vec3 grabTarget_ = Vec3::Zero();
    Vec3 grabOffset_ = Vec3::Zero(); // from the cursor to the vertex it picked up
    Index strokeStart_ = 0;
    std::vector<Stroke> strokes_;
    int sheet_ = 0;         // which sheet is in place: 0 the first, each Reset a new one
    SheetLook pressedLook_; // the sheet when the current stroke began
    MeshSize pressedMesh_;
    // A push pressed on a settled sheet leaves it settled until the tool comes near the
    // paper (AtTouch): pressed on the bare desk it moved nothing, yet ended the freeze,
    // and a scene's motions went on. Every other edit ends it at once.
    enum class Thaw { Now, AtTouch };
    void beginStroke(Thaw thaw = Thaw::Now);
    // Whether the tool, where it is now, is near enough the paper to touch it this step:
    // within its radius, a cell's length (a touch inside a cell is within that of each of
    // its corners), the step's move and a centimetre of a vertex.
    bool toolNearThePaper() const;
    bool thawAtTouch_ = false;
    double longestEdgeWhenPressed_ = 0.0;
    // One step of a settle under way: no damage; freezes the sheet once it rests.
    StepStatus settleStep();
    void freeze();
    enum class Settle { None, Settling, Frozen };
    // Damage is allowed only while neither settling nor frozen.
    void setSettle(Settle settle);
    Settle settle_ = Settle::None;
    bool pressedFrozen_ = false; // the sheet was settled when the current stroke began
    std::int64_t settleStart_ = 0;
    SheetLook settleLook_; // the sheet when Settle was chosen
    std::optional<StrokeEnd> finished_;
    std::vector<StrokeEnd> recounted_;
    // The world as the edit under way found it, while the newest step done is a Reset and
    // an undone step waits for its redo: should the edit become a step, the Reset's redo
    // gives this back (the damage since the undo is then the Reset's; keepStroke).
    std::shared_ptr<const World> resetSeenAt_;
    void noteWhatAResetSees();
    // A step's count of breaks and hinges changed (takeRecounted).
    void noteRecount(const Stroke& stroke);
    void noteRecount(const Stroke& stroke, int events);
    // The damage the sheet makes settling after the newest step joins that step only when
    // the next edit (or an undo) comes; its count is said as it grows, so that the
    // History names the step by what its undo would take back now, not a count that was
    // true at the let-go (a helper read "Fold (82 …)" over a sheet whose undo took back 86).
    void noteSettlingDamage();
    struct SettlingCount {
        int stroke = -1, sheet = -1;
        Index from = 0, scanned = 0; // the events counted: [from, scanned)
        int active = 0;              // of them, those still in place
        int said = -1;
    } settlingCount_;
    // The damage log's length after the last undo or redo (kNone once an edit began):
    // what lies beyond is the sheet settling since, which a redo takes back first.
    Index settledSince_ = kNone;
    // The fold under way: its first pin group in the world's script (the rest follow it
    // to the end), and when it is let go.
    static constexpr std::size_t kNoFold = static_cast<std::size_t>(-1);
    std::size_t foldGroup_ = kNoFold;
    double foldRelease_ = 0.0;
    // Ends the fold under way once its flap is let go (or a step failed): an undo step.
    void finishFold(bool letGo);
    // The fold's flap, watched for a second after its let-go, and what the watch read
    // (takeFoldTurnedBack, takeFoldLeftBehind); forgotten by any other edit.
    FoldWatch foldWatch_;
    std::optional<double> foldTurnedBack_, foldLeftBehind_;
    bool foldOpening_ = false;
    double foldAngle_ = 0.0;         // the angle the fold under way was asked for, radians
    FoldWatch::LeftOut foldLeftOut_; // what the carry of the fold under way does not hold
    void forgetFoldWatch();
    // Takes a sheet's pin groups still to be let go as the fold under way.
    void adoptFoldUnderWay();
    // Another edit must wait: a push or a grab is held, or a fold is under way.
    bool busy() const { return pressed_ || grabbing() || folding(); }
    EditLog log_; // endStep is filled in by log()
};

// Does `log` again from its start: steps to each command's step, applies it, and steps
// to the end. The result is bit for bit the session that was recorded. Returns an empty
// string, or why the replay stopped (a command before the current step, a failed step).
// `afterStep`, if given, runs after every step (to render frames, say); when it returns
// false the replay stops there.
std::string replay(const EditLog& log, EditSession& session,
                   const std::function<bool(const EditSession&)>& afterStep = {});

} // namespace pf

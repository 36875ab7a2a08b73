#include "EditSession.h"

#include "Breaking.h"
#include "Hinges.h"
#include "Integrator.h"
#include "Normals.h"
#include "Scenes.h"
#include "SheetStats.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

namespace pf {

EditSession::EditSession(World world) : sim_(std::move(world)) {
    // The user drives the sphere; a scene's scripted path would fight the mouse.
    sim_.world().script.sphereKeys.clear();
    toolTarget_ = sim_.world().sphere.center;
    adoptFoldUnderWay();
    beginLog();
}

EditSession::EditSession(const EditLog& log) : sim_(log.start) {
    sim_.world().script.sphereKeys.clear();
    toolTarget_ = log.toolTarget;
    pressed_ = log.pressed;
    if (pressed_) beginStroke(); // as replaceWorld did when the recording began
    adoptFoldUnderWay();
    beginLog();
}

void EditSession::beginLog() {
    log_.start = sim_.world();
    log_.toolTarget = toolTarget_;
    log_.pressed = pressed_;
    log_.commands.clear();
}

void EditSession::record(EditCommand command) {
    command.step = sim_.world().stepCount;
    log_.commands.push_back(std::move(command));
}

EditLog EditSession::log() const {
    EditLog out = log_;
    out.endStep = sim_.world().stepCount;
    out.endState = stateHash(sim_.world().sheet);
    return out;
}

void EditSession::apply(const EditCommand& c) {
    switch (c.kind) {
    case EditCommand::Kind::Tool:
        setTool(c.target, c.radius, c.visible, c.pressed);
        break;
    case EditCommand::Kind::PlaceTool:
        placeToolAtTarget();
        break;
    case EditCommand::Kind::Undo:
        undoStroke(c.stroke);
        break;
    case EditCommand::Kind::Redo:
        redoStroke(c.stroke);
        break;
    case EditCommand::Kind::Params:
        if (c.params) setParams(*c.params);
        break;
    case EditCommand::Kind::Diverged:
        advance(1);
        break;
    case EditCommand::Kind::Settle:
        settle();
        break;
    case EditCommand::Kind::Grab:
        grab(c.target, c.pressed, c.visible);
        break;
    case EditCommand::Kind::Pin:
        pin(c.target, c.radius);
        break;
    case EditCommand::Kind::Reset:
        if (c.world) reset(*c.world);
        break;
    case EditCommand::Kind::Fold:
        if (c.fold) fold(*c.fold);
        break;
    }
}

std::string replay(const EditLog& log, EditSession& session,
                   const std::function<bool(const EditSession&)>& afterStep) {
    auto stepTo = [&](std::int64_t step) -> std::string {
        const std::int64_t now = session.world().stepCount;
        if (step < now)
            return "a command at step " + std::to_string(step) + " comes after step " +
                   std::to_string(now);
        while (session.world().stepCount < step) {
            const std::int64_t left = step - session.world().stepCount;
            const int n = afterStep ? 1 : static_cast<int>(std::min<std::int64_t>(left, 1 << 20));
            if (session.advance(n) != StepStatus::Ok)
                return "the step after " + std::to_string(session.world().stepCount) +
                       " blew up (its result was not finite, or flew apart), where the "
                       "recorded session's did not; the sheet is kept as it was before that "
                       "step";
            if (afterStep && !afterStep(session))
                return "stopped after step " + std::to_string(session.world().stepCount);
        }
        return {};
    };
    for (const EditCommand& c : log.commands) {
        if (std::string error = stepTo(c.step); !error.empty()) return error;
        if (c.kind == EditCommand::Kind::Diverged) {
            // The editor's step failed here and it paused; the same attempt must fail.
            if (session.advance(1) == StepStatus::Ok)
                return "the step after " + std::to_string(c.step) +
                       " failed in the session but not in the replay";
            continue;
        }
        session.apply(c);
    }
    return stepTo(log.endStep);
}

void EditSession::replaceWorld(const World& world) {
    setSettle(Settle::None);
    finished_.reset();    // an undo step of the old sheet's
    foldGroup_ = kNoFold; // a fold of the old sheet's
    forgetFoldWatch();
    const SphereTool tool = sim_.world().sphere;
    const int threads = sim_.threads();
    sim_ = Simulation(world);
    sim_.setThreads(threads);
    sim_.world().script.sphereKeys.clear();
    sim_.world().sphere.radius = tool.radius;
    sim_.world().sphere.active = tool.active;
    sim_.world().sphere.hovering = tool.hovering;
    grabbed_ = kNone; // a vertex of the old sheet (the new Simulation holds none)
    strokes_.clear();
    recounted_.clear();
    settlingCount_ = {}; // its stroke numbers start again
    resetSeenAt_.reset();
    sheet_ = 0;
    // A stroke held across New goes on from the new sheet.
    if (pressed_) beginStroke();
    adoptFoldUnderWay();
    beginLog();
}

void EditSession::setParams(const SimParams& given) {
    SimParams params = given;
    params.sigma = sim_.world().params.sigma; // a look, which the editor keeps (Params.h)
    EditCommand c;
    c.kind = EditCommand::Kind::Params;
    c.params = std::make_shared<const SimParams>(params);
    record(std::move(c));
    setSettle(Settle::None); // an edit ends a freeze (and a settle under way)
    if (!(params.material == sim_.world().params.material))
        setMaterial(sim_.world(), params.material);
    // xpbd reads an edge's contraction on the arc, the others on the chord: peaks kept
    // in one reading would set off a burst of breaks in the other (or hold them back).
    if (keepsEdgeLengths(params.integrator) != keepsEdgeLengths(sim_.world().params.integrator))
        recordCurrentContraction(sim_.world().sheet, params);
    sim_.world().params = params;
    sim_.sheetEdited(); // φ weighs Eq. 10
}

std::optional<EditSession::StrokeEnd> EditSession::setTool(const Vec3& target, double radius,
                                                           bool visible, bool pressed) {
    EditCommand c = EditCommand::of(EditCommand::Kind::Tool);
    c.target = target;
    c.radius = radius;
    c.visible = visible;
    c.pressed = pressed;
    record(std::move(c));
    SphereTool& sphere = sim_.world().sphere;
    toolTarget_ = target;
    sphere.radius = radius;
    // It appears where the cursor is; a hovering sphere pressed goes down from where it
    // hovers.
    if (visible && !sphere.active && !sphere.hovering) sphere.center = target;
    if (grabbing() || folding()) pressed = false; // one stroke at a time
    sphere.active = visible && pressed;
    sphere.hovering = visible && !pressed;
    if (pressed && !pressed_) beginStroke(Thaw::AtTouch);
    const bool released = pressed_ && !pressed;
    if (released) thawAtTouch_ = false; // it never came near: the sheet stays settled
    pressed_ = pressed;
    return released ? endStroke(StrokeKind::Push) : std::nullopt;
}

std::optional<EditSession::StrokeEnd> EditSession::grab(const Vec3& target, bool held, bool begin) {
    EditCommand c = EditCommand::of(EditCommand::Kind::Grab);
    c.target = target;
    c.visible = begin;
    c.pressed = held;
    record(std::move(c));
    const World& w = sim_.world();
    // Only an explicit begin picks up: after an undo let go, moves of the hand that
    // still holds nothing must not pick up whatever is nearest.
    if (begin && held && !busy()) {
        const auto& V = w.sheet.verts;
        double nearest = std::numeric_limits<double>::infinity();
        for (Index i = 0; i < V.size(); ++i) {
            const double d = (V.x[i] - target).squaredNorm();
            if (!V.pinned[i] && d < nearest) {
                nearest = d;
                grabbed_ = i;
            }
        }
        if (grabbing()) {
            // The hand holds the paper where it took it: the vertex keeps its offset from
            // the cursor. Drawn onto the cursor instead, a vertex picked up a few
            // millimetres away was yanked across the sheet and tore it at once.
            grabOffset_ = V.x[grabbed_] - target;
            beginStroke();
            setPins({grabbed_}, true);
            sim_.setHeldVertex(grabbed_);
        }
    }
    grabTarget_ = target + grabOffset_;
    if (w.groundEnabled) grabTarget_.y() = std::max(grabTarget_.y(), w.groundHeight);
    if (begin && held) return std::nullopt;
    if (held || !grabbing()) return std::nullopt;
    releaseGrab();
    return endStroke(StrokeKind::Grab);
}

void EditSession::releaseGrab() {
    if (!grabbing()) return;
    setPins({grabbed_}, false); // it keeps its velocity: a throw
    grabbed_ = kNone;
    grabOffset_ = Vec3::Zero();
    sim_.setHeldVertex(kNone);
}

double EditSession::grabHeldBack() const {
    if (!grabbing()) return 0.0;
    const auto& V = sim_.world().sheet.verts;
    for (Index i = 0; i < V.size(); ++i)
        if (V.pinned[i] && i != grabbed_) return (V.x[grabbed_] - grabTarget_).norm();
    return 0.0;
}

World EditSession::worldToSave() const {
    World w = sim_.world();
    if (grabbing()) w.sheet.verts.pinned[grabbed_] = 0; // held by the hand, not pinned
    return w;
}

void EditSession::pullGrabbed() {
    if (!grabbing()) return;
    auto& V = sim_.world().sheet.verts;
    V.v[grabbed_] = boundedMove(V.x[grabbed_], grabTarget_, kMaxHandSpeed) / sim_.world().params.dt;
}

void EditSession::setPins(const std::vector<Index>& vertices, bool pinned) {
    Sheet& sheet = sim_.world().sheet;
    sheet.paper.wake(); // what held it may be gone
    auto& V = sheet.verts;
    for (Index i : vertices) {
        if (i < 0 || i >= V.size()) continue;
        V.pinned[i] = pinned ? 1 : 0;
        if (pinned) V.v[i] = Vec3::Zero();
    }
    sim_.sheetEdited();
}

std::optional<EditSession::StrokeEnd> EditSession::pin(const Vec3& point, double radius) {
    EditCommand c = EditCommand::of(EditCommand::Kind::Pin);
    c.target = point;
    c.radius = radius;
    record(std::move(c));
    if (busy()) return std::nullopt;
    const auto& V = sim_.world().sheet.verts;
    // A click within reach of a pin frees it, even where free paper lies a little nearer
    // the click: paper that hangs from a pin falls steeply away round it (xpbd's does not
    // stretch), and the nearest vertex to a second click on the pin was free paper. But a
    // click on free paper clearly nearer than any pin pins it: between two pins a column
    // apart, a click on the free column between them freed a whole row of pins.
    Index nearestFree = kNone, nearestPinned = kNone;
    double bestFree = radius * radius, bestPinned = radius * radius;
    for (Index i = 0; i < V.size(); ++i) {
        const double d = (V.x[i] - point).squaredNorm();
        Index& nearest = V.pinned[i] ? nearestPinned : nearestFree;
        double& best = V.pinned[i] ? bestPinned : bestFree;
        if (d <= best) {
            best = d;
            nearest = i;
        }
    }
    const double onPin = kOnPinShare * kOnPinShare * radius * radius;
    const bool freeing = nearestPinned != kNone && (nearestFree == kNone || bestPinned <= onPin ||
                                                    bestPinned <= 4.0 * bestFree);
    const Index nearest = freeing ? nearestPinned : nearestFree;
    if (nearest == kNone) return std::nullopt;
    const bool to = !V.pinned[nearest];
    std::vector<Index> changed;
    if (to) {
        for (Index i = 0; i < V.size(); ++i)
            if (!V.pinned[i] && (V.x[i] - point).squaredNorm() <= radius * radius)
                changed.push_back(i);
    } else if (const Stroke* set = pinThatHeld(nearest)) {
        // The pin the user set there, as one click set it: three clicks side by side made
        // one patch of pins, and a click on one freed all 14 of its vertices.
        for (Index i : set->pinChanged)
            if (i < V.size() && V.pinned[i]) changed.push_back(i);
    } else {
        // A pin this session did not set (opened with the sheet): the whole pinned patch
        // the click landed on, pinned vertices joined by springs, up to kPinPatchReach
        // radii from the click. The paper round a pin moves, so a second click on the
        // pin meets it a little off where the first did, and must still free all of it;
        // a pin further off is another pin.
        const Springs& S = sim_.world().sheet.springs;
        const double reach2 = kPinPatchReach * kPinPatchReach * radius * radius;
        auto inPatch = [&](Index i) {
            return V.pinned[i] && (V.x[i] - point).squaredNorm() <= reach2;
        };
        std::vector<std::vector<Index>> joined(static_cast<std::size_t>(V.size()));
        for (Index k = 0; k < S.size(); ++k)
            if (inPatch(S.a[k]) && inPatch(S.b[k])) {
                joined[static_cast<std::size_t>(S.a[k])].push_back(S.b[k]);
                joined[static_cast<std::size_t>(S.b[k])].push_back(S.a[k]);
            }
        std::vector<std::uint8_t> taken(static_cast<std::size_t>(V.size()), 0);
        changed.push_back(nearest);
        taken[static_cast<std::size_t>(nearest)] = 1;
        for (std::size_t k = 0; k < changed.size(); ++k)
            for (Index j : joined[static_cast<std::size_t>(changed[k])])
                if (!taken[static_cast<std::size_t>(j)]) {
                    taken[static_cast<std::size_t>(j)] = 1;
                    changed.push_back(j);
                }
    }
    beginStroke();
    setPins(changed, to);
    Stroke stroke;
    closeStroke(stroke);
    stroke.pinnedTo = to;
    stroke.pinChanged = std::move(changed);
    StrokeEnd end = keepStroke(std::move(stroke), to ? StrokeKind::Pin : StrokeKind::Unpin);
    end.events = static_cast<int>(strokes_.back().pinChanged.size());
    return end;
}

const EditSession::Stroke* EditSession::pinThatHeld(Index vertex) const {
    for (auto st = strokes_.rbegin(); st != strokes_.rend(); ++st) {
        // A step on another sheet (before a Reset) numbered other vertices.
        if (!st->applied || st->pinChanged.empty() || st->sheet != sheet_) continue;
        if (std::find(st->pinChanged.begin(), st->pinChanged.end(), vertex) == st->pinChanged.end())
            continue;
        // The newest step that set or freed this vertex: a pin only if it set it.
        return st->pinnedTo ? &*st : nullptr;
    }
    return nullptr;
}

void EditSession::shiftScript(std::vector<PinGroup>& pins, double shift) {
    for (PinGroup& g : pins) {
        g.start += shift;
        g.until += shift;
        g.release += shift;
    }
}

EditSession::SheetLook EditSession::look() const {
    const World& w = sim_.world();
    return {w.sheet.verts.x, w.sheet.verts.v, w.sheet.paper, w.script.pins, w.time};
}

bool EditSession::restore(const SheetLook& look) {
    Sheet& s = sim_.world().sheet;
    if (look.x.size() != static_cast<std::size_t>(s.verts.size())) return false;
    s.verts.x = look.x;
    s.verts.v = look.v;
    s.paper = look.paper;
    // The scene's own motions as they were then too, going on from now: given back
    // mid-gather at a later time of the script, crumple-cycles' rim was where the script
    // had not yet brought it, and the next pull flat stretched the sheet 111-159 % (a
    // helper's session, Reset undone and redone with two pushes).
    World& w = sim_.world();
    w.script.pins = look.scriptPins;
    shiftScript(w.script.pins, w.time - look.time);
    sim_.restartIntegrator();
    return true;
}

EditSession::MeshSize EditSession::meshSize() const {
    const Sheet& s = sim_.world().sheet;
    return {s.verts.size(), s.springs.size(), s.triangleCount()};
}

void EditSession::noteWhatAResetSees() {
    resetSeenAt_.reset();
    if (newestReset() && redoWaiting()) resetSeenAt_ = std::make_shared<const World>(worldToSave());
}

void EditSession::beginStroke(Thaw thaw) {
    forgetFoldWatch(); // the next edit came first
    noteWhatAResetSees();
    // While a redo waits, the damage since the undo is no stroke's yet: an edit that ends
    // as an undo step gives it to the stroke before it then (keepStroke), and one that
    // does not (a press that moved nothing) leaves it for the redo to take back.
    if (!redoWaiting()) {
        keepSettlingWithLastStroke();
        settledSince_ = kNone;
    }
    pressedFrozen_ = settle_ == Settle::Frozen;
    if (thaw == Thaw::AtTouch && settle_ == Settle::Frozen) {
        thawAtTouch_ = true;
        const Sheet& s = sim_.world().sheet;
        double longest2 = 0.0;
        for (Index e = 0; e < s.springs.size(); ++e)
            if (s.springs.kind[e] == SpringKind::Structural)
                longest2 =
                    std::max(longest2,
                             (s.verts.x[s.springs.a[e]] - s.verts.x[s.springs.b[e]]).squaredNorm());
        longestEdgeWhenPressed_ = std::sqrt(longest2);
    } else {
        setSettle(Settle::None);
    }
    strokeStart_ = static_cast<Index>(sim_.world().sheet.events.size());
    pressedLook_ = look();
    pressedMesh_ = meshSize();
}

std::optional<EditSession::StrokeEnd> EditSession::endStroke(StrokeKind kind) {
    const Sheet& s = sim_.world().sheet;
    Stroke stroke;
    appendEvents(stroke, strokeStart_, static_cast<Index>(s.events.size()));
    bool moved = stroke.events.size() > 0 || pressedLook_.x.size() != s.verts.x.size();
    for (std::size_t i = 0; !moved && i < pressedLook_.x.size(); ++i)
        moved = (s.verts.x[i] - pressedLook_.x[i]).squaredNorm() > kStrokeMoves * kStrokeMoves;
    if (!moved) return std::nullopt;
    closeStroke(stroke);
    return keepStroke(std::move(stroke), kind);
}

void EditSession::closeStroke(Stroke& stroke) {
    stroke.firstEvent = strokeStart_;
    stroke.pressedOn = pressedMesh_;
    stroke.frozenBefore = pressedFrozen_;
    stroke.before = std::exchange(pressedLook_, {});
    stroke.after = look();
}

Vec3 EditSession::boundedMove(const Vec3& from, const Vec3& to, double speed) const {
    Vec3 move = to - from;
    const double limit = speed * sim_.world().params.dt;
    if (move.norm() > limit) move *= limit / move.norm();
    return move;
}

void EditSession::appendEvents(Stroke& stroke, Index from, Index to) const {
    const Sheet& s = sim_.world().sheet;
    for (Index e = from; e < to; ++e) {
        const DamageEvent& ev = s.events[e];
        if (!ev.active) continue;
        StrokeEvent se{e, ev.kind, ev.edge, 0.0, 0.0, ev.step};
        if (ev.kind == EventKind::Hinge) se.hingeRest = s.springs.rest[ev.springs[0]];
        if (ev.kind == EventKind::Break) se.creaseRest = s.springs.rest[ev.edge];
        stroke.events.push_back(se);
    }
}

void EditSession::noteRecount(const Stroke& stroke) {
    noteRecount(stroke, static_cast<int>(stroke.events.size()));
}

void EditSession::noteRecount(const Stroke& stroke, int events) {
    // A pin's step is named by its vertices, a Settle and a Reset by nothing counted.
    if (stroke.kind != StrokeKind::Push && stroke.kind != StrokeKind::Grab &&
        stroke.kind != StrokeKind::Fold)
        return;
    const int index = static_cast<int>(&stroke - strokes_.data());
    auto same = std::ranges::find(recounted_, index, &StrokeEnd::stroke);
    if (same != recounted_.end())
        same->events = events;
    else
        recounted_.push_back({index, events, stroke.kind});
}

void EditSession::noteSettlingDamage() {
    // As keepSettlingWithLastStroke would take it now, without taking it: the step's look
    // is kept only when the next edit comes.
    if (busy() || redoWaiting() || newestReset()) return;
    const Stroke* last = newestApplied();
    if (!last || last->sheet != sheet_ || last->worldAfter) return;
    const int index = static_cast<int>(last - strokes_.data());
    SettlingCount& c = settlingCount_;
    const auto& events = sim_.world().sheet.events;
    const Index end = static_cast<Index>(events.size());
    // Counted afresh for another step, another sheet (a Reset, or its undo), or a log
    // shorter than what was counted (the log only grows, but a count must not outlive it).
    if (c.stroke != index || c.sheet != sheet_ || c.from != last->endEvent || end < c.scanned)
        c = {index,          sheet_, last->endEvent,
             last->endEvent, 0,      static_cast<int>(last->events.size())};
    for (; c.scanned < end; ++c.scanned)
        if (events[static_cast<std::size_t>(c.scanned)].active) ++c.active;
    const int count = static_cast<int>(last->events.size()) + c.active;
    if (count == c.said) return;
    c.said = count;
    noteRecount(*last, count);
}

std::vector<EditSession::StrokeEnd> EditSession::takeRecounted() {
    return std::exchange(recounted_, {});
}

EditSession::Stroke* EditSession::newestReset() {
    Stroke* newest = newestApplied();
    return newest && newest->worldAfter && newest->sheetAfter == sheet_ ? newest : nullptr;
}

EditSession::Stroke* EditSession::newestApplied() {
    auto done = std::find_if(strokes_.rbegin(), strokes_.rend(),
                             [](const Stroke& st) { return st.applied; });
    return done == strokes_.rend() ? nullptr : &*done;
}

bool EditSession::redoWaiting() const {
    for (auto st = strokes_.rbegin(); st != strokes_.rend() && !st->applied; ++st)
        if (!st->worldAfter && st->sheet == sheet_) return true;
    return false;
}

void EditSession::keepSettlingWithLastStroke(bool forALaterRedo) {
    // A Reset's step is the world it put in place; what that sheet did since (breaks
    // included: crumple-cycles' pins gather it at once) is that world now. Its redo gives
    // it back, so the next step is redone on the mesh it began on.
    if (Stroke* reset = newestReset()) {
        // (Without the hand's pin: a held grab is no pin of the sheet's.)
        if (!forALaterRedo) reset->worldAfter = std::make_shared<const World>(worldToSave());
        return;
    }
    keepSettlingWithLastStroke(static_cast<Index>(sim_.world().sheet.events.size()), look(),
                               forALaterRedo);
}

void EditSession::keepSettlingWithLastStroke(Index until, SheetLook then, bool forALaterRedo) {
    Stroke* newest = newestApplied();
    if (!newest) return;
    Stroke& last = *newest;
    if (last.sheet != sheet_ || last.worldAfter) return;
    if (!forALaterRedo)
        last.sinceLaterUndo.reset();
    else if (!last.sinceLaterUndo)
        last.sinceLaterUndo = last.events.size();
    // The damage even of a step too old to keep its look (kStrokesWithLook): the next
    // step began on the mesh with it.
    const std::size_t had = last.events.size();
    appendEvents(last, last.endEvent, until);
    if (last.events.size() != had) noteRecount(last);
    last.endEvent = until;
    if (!last.after.x.empty()) last.after = std::move(then);
}

EditSession::StrokeEnd EditSession::keepStroke(Stroke stroke, StrokeKind kind) {
    // The step drops the redos that waited (the editor's History does): the damage since
    // their undo is the stroke's before it now, up to where this one began.
    if (redoWaiting() && !stroke.worldAfter) {
        if (Stroke* reset = newestReset(); reset && resetSeenAt_)
            reset->worldAfter = resetSeenAt_;
        else
            keepSettlingWithLastStroke(stroke.firstEvent, stroke.before);
    }
    resetSeenAt_.reset();
    stroke.sheet = sheet_;
    stroke.kind = kind;
    stroke.endEvent = static_cast<Index>(sim_.world().sheet.events.size());
    stroke.applied = true;
    settledSince_ = kNone;
    strokes_.push_back(std::move(stroke));
    if (strokes_.size() > kStrokesWithLook) {
        Stroke& old = strokes_[strokes_.size() - 1 - kStrokesWithLook];
        old.before = {};
        old.after = {};
    }
    return StrokeEnd{static_cast<int>(strokes_.size()) - 1,
                     static_cast<int>(strokes_.back().events.size()), kind};
}

std::optional<EditSession::StrokeEnd> EditSession::reset(const World& world) {
    EditCommand c;
    c.kind = EditCommand::Kind::Reset;
    c.world = std::make_shared<const World>(world);
    record(c);
    if (pressed_ || folding()) return std::nullopt; // it would go on across two sheets
    finished_.reset(); // a settle of the sheet going away is no step of the new one
    releaseGrab();     // before the copy: the hand's pin is not the sheet's
    // Its undo gives back this sheet, which a redo of the step before it then gives back
    // too; the redos that waited are dropped.
    keepSettlingWithLastStroke();
    Stroke st;
    st.worldBefore = std::make_shared<const World>(sim_.world());
    st.frozenBefore = settle_ == Settle::Frozen; // its undo freezes it again
    st.worldAfter = c.world;
    st.sheetBefore = sheet_;
    // Numbered by the Reset's own undo step, unique in the session (0 is the first).
    st.sheetAfter = static_cast<int>(strokes_.size()) + 1;
    swapSheet(*st.worldAfter, st.sheetAfter);
    return keepStroke(std::move(st), StrokeKind::Reset);
}

void EditSession::swapSheet(const World& world, int sheet) {
    forgetFoldWatch(); // a Reset, or its undo or redo: the flap watched is gone
    releaseGrab();
    setSettle(Settle::None);
    const World& now = sim_.world();
    const SphereTool tool = now.sphere;
    const std::int64_t step = now.stepCount;
    const double time = now.time;
    const int threads = sim_.threads();
    sim_ = Simulation(world);
    sim_.setThreads(threads);
    World& w = sim_.world();
    w.script.sphereKeys.clear();
    w.sphere = tool;
    w.stepCount = step;
    // The clock runs on (commands stay in step order), so the incoming sheet's script
    // moves with it: a fresh scene starts its pins' motions now, and a sheet given back
    // by an undo goes on from where it was. Left at the old times, a Reset of
    // crumple-cycles mid-gather pulled the flat rim out to twice its size.
    shiftScript(w.script.pins, time - w.time);
    w.time = time;
    sheet_ = sheet;
    settledSince_ = kNone;
}

std::optional<int> EditSession::undoStroke(int stroke) {
    EditCommand c = EditCommand::of(EditCommand::Kind::Undo);
    c.stroke = stroke;
    record(std::move(c));
    if (stroke < 0 || stroke >= static_cast<int>(strokes_.size()) || folding()) return std::nullopt;
    // A step that is not done (undone, or its redo refused) has nothing to take back: from
    // where it once began, recovery would take the damage of the steps done since.
    if (!strokes_[static_cast<std::size_t>(stroke)].applied) return std::nullopt;
    forgetFoldWatch(); // recovery renumbers vertices
    const Stroke& st = strokes_[static_cast<std::size_t>(stroke)];
    if (st.worldAfter) { // a Reset
        if (sheet_ != st.sheetAfter || pressed_) return std::nullopt;
        // As the newest step, its redo gives back the sheet as it is now (as a stroke's).
        if (newestApplied() == &st && !redoWaiting()) keepSettlingWithLastStroke();
        swapSheet(*st.worldBefore, st.sheetBefore);
        if (st.frozenBefore) freeze();
        strokes_[static_cast<std::size_t>(stroke)].applied = false;
        return 0;
    }
    if (st.sheet != sheet_) return std::nullopt; // made on a sheet a Reset replaced
    releaseGrab();                               // its vertex may be recovered away
    // Undoing the newest step ends its settling: a redo gives back the sheet as the user
    // last saw it, not as the stroke left it (a fold that had settled for two minutes
    // came back as it was at the let-go, and broke on from there).
    // While a later step waits for its redo, what the sheet broke since is kept apart: this
    // step's redo gives it back, and the later step's redo takes it back first.
    if (newestApplied() == &st) keepSettlingWithLastStroke(redoWaiting());
    Sheet& s = sim_.world().sheet;
    int recovered = 0;
    bool all = true;
    for (Index e = static_cast<Index>(s.events.size()) - 1; e >= st.firstEvent; --e) {
        if (!s.events[e].active) continue;
        const bool ok = recoverEvent(s, e);
        recovered += ok ? 1 : 0;
        all = all && ok;
    }
    setPins(st.pinChanged, !st.pinnedTo);
    sim_.sheetEdited();
    setSettle(Settle::None);
    strokes_[static_cast<std::size_t>(stroke)].applied = false;
    settledSince_ = static_cast<Index>(s.events.size());
    // A stroke that began on a settled sheet gives it back settled.
    if (all && restore(st.before) && st.frozenBefore && !pressed_) freeze();
    if (pressed_) beginStroke(); // a stroke under way goes on from what undo left
    return recovered;
}

std::optional<int> EditSession::redoStroke(int stroke) {
    EditCommand c = EditCommand::of(EditCommand::Kind::Redo);
    c.stroke = stroke;
    record(std::move(c));
    if (stroke < 0 || stroke >= static_cast<int>(strokes_.size()) || folding()) return std::nullopt;
    if (strokes_[static_cast<std::size_t>(stroke)].applied) return std::nullopt; // done already
    forgetFoldWatch(); // recovery renumbers vertices
    if (Stroke& reset = strokes_[static_cast<std::size_t>(stroke)]; reset.worldAfter) {
        if (sheet_ != reset.sheetBefore || pressed_) return std::nullopt;
        // The sheet moved on since the undo: an undo of this redo gives back that.
        releaseGrab();
        reset.worldBefore = std::make_shared<const World>(sim_.world());
        reset.frozenBefore = settle_ == Settle::Frozen;
        swapSheet(*reset.worldAfter, reset.sheetAfter);
        reset.applied = true;
        // What its sheet breaks from now on (crumple-cycles' pins go on gathering it) is
        // taken back by the next step's redo, which needs the mesh that step began on.
        settledSince_ = static_cast<Index>(sim_.world().sheet.events.size());
        return 0;
    }
    if (strokes_[static_cast<std::size_t>(stroke)].sheet != sheet_) return std::nullopt;
    World& w = sim_.world();
    Sheet& s = w.sheet;
    // A stroke under way that broke the sheet: its damage lies beyond what the redo takes
    // back first, newest first, so it would go too (and belong to no step).
    if (pressed_ || grabbing())
        for (Index e = strokeStart_; e < static_cast<Index>(s.events.size()); ++e)
            if (s.events[e].active) return std::nullopt;
    releaseGrab();
    Stroke& st = strokes_[static_cast<std::size_t>(stroke)];
    // What the sheet broke settling since the last undo or redo goes: the redo gives
    // back the sheet as the next edit found it, and its edge ids are those of the mesh
    // the stroke began on, which that damage changed (the editor plays on between the
    // clicks of several redos).
    if (settledSince_ != kNone) {
        for (Index e = static_cast<Index>(s.events.size()) - 1; e >= settledSince_; --e)
            if (s.events[e].active) recoverEvent(s, e);
        // What the step below took of it while this one waited is gone now: done again,
        // that step must not bring it back.
        if (Stroke* below = newestApplied(); below && below->sinceLaterUndo) {
            const std::size_t had = below->events.size();
            below->events.resize(*below->sinceLaterUndo);
            below->sinceLaterUndo.reset();
            if (below->events.size() != had) noteRecount(*below);
        }
    }
    // Edge ids are the stroke's only on the mesh it began on: anything else (another
    // stroke still applied) would break other edges.
    if (!(meshSize() == st.pressedOn) || s.events.size() + st.events.size() > kMaxDamageEvents)
        return std::nullopt;
    st.firstEvent = static_cast<Index>(s.events.size());
    int reapplied = 0;
    std::vector<Vec3> normals;
    Index laterUndoFrom = kNone; // where the damage since a later step's undo begins again
    for (std::size_t k = 0; k < st.events.size(); ++k) {
        StrokeEvent& se = st.events[k];
        if (st.sinceLaterUndo && k == *st.sinceLaterUndo)
            laterUndoFrom = static_cast<Index>(s.events.size());
        // Undone in reverse order, the edges have their old ids again.
        if (se.edge < 0 || se.edge >= s.springs.size()) continue;
        if (se.kind == EventKind::Break) {
            if (!canBreak(s, se.edge)) continue;
            computeVertexNormals(s, normals);
            se.event = breakEdge(s, se.edge, normals, w.params.psi, se.step,
                                 keepsEdgeLengths(w.params.integrator));
            s.springs.rest[se.edge] = se.creaseRest; // the crease as the stroke left it
        } else {
            if (!canHinge(s, se.edge)) continue;
            se.event = insertHinge(s, se.edge, se.hingeRest, se.step);
        }
        ++reapplied;
    }
    setPins(st.pinChanged, st.pinnedTo);
    sim_.sheetEdited();
    setSettle(Settle::None);
    st.endEvent = static_cast<Index>(s.events.size());
    st.applied = true;
    // The later step that waits began on the mesh without the damage since its undo.
    settledSince_ = laterUndoFrom != kNone ? laterUndoFrom : st.endEvent;
    const bool restored = reapplied == static_cast<int>(st.events.size()) && restore(st.after);
    if (st.settle && restored && !pressed_) freeze();
    if (pressed_) beginStroke();
    return reapplied;
}

StepStatus EditSession::advance(int steps) {
    World& w = sim_.world();
    for (int k = 0; k < steps; ++k) {
        SphereTool& sphere = w.sphere;
        const Vec3 move = boundedMove(sphere.center, toolTarget_);
        sphere.center += move;
        sphere.velocity = move / w.params.dt;
        pullGrabbed();
        if (thawAtTouch_ && sphere.active && toolNearThePaper()) setSettle(Settle::None);
        // While the sheet settles or stands settled the scene's motions wait: their
        // times move on with the clock.
        if (settle_ != Settle::None) shiftScript(w.script.pins, w.params.dt);
        if (settle_ == Settle::Frozen) {
            // Kept as it is: the clock runs (commands stay stamped in order), nothing moves.
            ++w.stepCount;
            w.time += w.params.dt;
            continue;
        }
        const StepStatus status = settle_ == Settle::Settling ? settleStep() : sim_.step();
        if (status != StepStatus::Ok) {
            noteSettlingDamage(); // what the good steps before it broke
            record(EditCommand::of(EditCommand::Kind::Diverged));
            // The carry is what blew up, maybe: let the flap go rather than carry it on.
            if (folding()) finishFold(false);
            return status;
        }
        if (folding() && w.time >= foldRelease_) finishFold(true);
        if (foldWatch_.openingEarly(w.sheet, w.time, kSprangBack)) foldOpening_ = true;
        if (const auto reading = foldWatch_.check(w.sheet, w.time)) {
            foldTurnedBack_ = reading->turnedBack;
            if (reading->unfoldedShare > 0.0) foldLeftBehind_ = reading->unfoldedShare;
        }
    }
    noteSettlingDamage();
    return StepStatus::Ok;
}

bool EditSession::placeToolAtTarget() {
    SphereTool& sphere = sim_.world().sphere;
    if ((sphere.center - toolTarget_).squaredNorm() == 0.0) return false;
    record(EditCommand::of(EditCommand::Kind::PlaceTool));
    sphere.center = toolTarget_;
    return true;
}

void EditSession::settle() {
    record(EditCommand::of(EditCommand::Kind::Settle));
    // Not under a held tool: the stroke would go on through paper that cannot break.
    if (settle_ != Settle::None || busy()) return;
    forgetFoldWatch(); // frozen, the flap would be read only when something thaws it
    if (!redoWaiting()) keepSettlingWithLastStroke();
    noteWhatAResetSees();
    setSettle(Settle::Settling);
    settleStart_ = sim_.world().stepCount;
    settleLook_ = look();
}

bool EditSession::toolNearThePaper() const {
    const World& w = sim_.world();
    // (It came this step's move, up to 15 cm at the largest time step.)
    const double reach =
        w.sphere.radius + longestEdgeWhenPressed_ + w.sphere.velocity.norm() * w.params.dt + 0.01;
    for (const Vec3& x : w.sheet.verts.x)
        if ((x - w.sphere.center).squaredNorm() < reach * reach) return true;
    return false;
}

void EditSession::setSettle(Settle settle) {
    thawAtTouch_ = false;
    settle_ = settle;
    sim_.allowDamage(settle == Settle::None);
    // "Keep it like this": a scene's motions wait too (crumple-cycles' rim pulled the
    // sheet flat while it settled), and go on from where they stood at the next edit.
    sim_.holdScript(settle != Settle::None);
}

StepStatus EditSession::settleStep() {
    const StepStatus status = sim_.step();
    if (status != StepStatus::Ok) return status;
    const World& w = sim_.world();
    double fastest = 0.0;
    for (const Vec3& v : w.sheet.verts.v) fastest = std::max(fastest, v.squaredNorm());
    const bool resting = fastest < kRestSpeed * kRestSpeed;
    if (resting || double(w.stepCount - settleStart_) * w.params.dt >= kSettleSeconds) {
        Stroke stroke;
        stroke.firstEvent = static_cast<Index>(w.sheet.events.size());
        stroke.pressedOn = meshSize();
        stroke.before = std::move(settleLook_);
        settleLook_ = {};
        freeze();
        stroke.after = look();
        stroke.settle = true;
        finished_ = keepStroke(std::move(stroke), StrokeKind::Settle);
    }
    return status;
}

void EditSession::freeze() {
    for (Vec3& v : sim_.world().sheet.verts.v) v.setZero();
    sim_.restartIntegrator();
    setSettle(Settle::Frozen);
}

void EditSession::forgetFoldWatch() {
    foldWatch_.cancel();
    foldTurnedBack_.reset();
    foldLeftBehind_.reset();
    foldOpening_ = false;
}

std::optional<double> EditSession::takeFoldTurnedBack() {
    return std::exchange(foldTurnedBack_, std::nullopt);
}

std::optional<double> EditSession::takeFoldLeftBehind() {
    return std::exchange(foldLeftBehind_, std::nullopt);
}

std::optional<EditSession::FoldNotice> EditSession::foldNotice(std::optional<double> turnedBack,
                                                               std::optional<double> leftBehind,
                                                               double askedDegrees) {
    // A flap that opened again is the larger news: what it left behind opened with it.
    if (turnedBack && *turnedBack > kSprangBack)
        return FoldNotice{FoldNotice::Kind::SprangBack, std::min(*turnedBack, askedDegrees)};
    if (turnedBack && *turnedBack < -kSprangBack) {
        const double closed = -*turnedBack;
        if (askedDegrees + closed >= 180.0 - kShutWithin)
            return FoldNotice{FoldNotice::Kind::FellShut, askedDegrees};
        return FoldNotice{FoldNotice::Kind::ClosedFurther, closed};
    }
    if (leftBehind && *leftBehind >= kLeftBehindShare)
        return FoldNotice{FoldNotice::Kind::LeftPaperBehind, *leftBehind};
    return std::nullopt;
}

std::optional<EditSession::StrokeEnd> EditSession::takeFinished() {
    return std::exchange(finished_, std::nullopt);
}

FoldRefusal EditSession::fold(const FoldRequest& request) {
    // What a recording could not hold again (a line drawn toward the horizon) changes
    // nothing, so it is refused before it is recorded.
    auto near = [](const Vec3& p, double limit) { return p.allFinite() && p.norm() <= limit; };
    if (!near(request.from, kDivergenceRadius) || !near(request.to, kDivergenceRadius) ||
        !near(request.viewer, 10.0))
        return FoldRefusal::OffSheet;
    EditCommand c = EditCommand::of(EditCommand::Kind::Fold);
    c.fold = std::make_shared<const FoldRequest>(request);
    record(std::move(c));
    if (busy()) return FoldRefusal::Busy;
    FoldPlan plan = planFold(sim_.world(), request);
    if (plan.refusal != FoldRefusal::None) return plan.refusal;
    beginStroke();
    for (const PinGroup& g : plan.motions) setPins(g.vertices, true);
    foldRelease_ = plan.release;
    foldAngle_ = request.angle;
    foldLeftOut_ = std::move(plan.leftOut);
    auto& groups = sim_.world().script.pins;
    foldGroup_ = groups.size();
    for (PinGroup& g : plan.motions) groups.push_back(std::move(g));
    return FoldRefusal::None;
}

void EditSession::adoptFoldUnderWay() {
    // A sheet saved in the middle of a fold (or a scene that folds) goes on folding: the
    // groups still to be let go are the fold under way, one undo step when let go.
    const World& w = sim_.world();
    const auto& groups = w.script.pins;
    foldGroup_ = kNoFold;
    for (std::size_t g = 0; g < groups.size(); ++g) {
        if (!std::isfinite(groups[g].release) || groups[g].release <= w.time) continue;
        if (foldGroup_ == kNoFold) foldGroup_ = g;
        foldRelease_ =
            foldGroup_ == g ? groups[g].release : std::max(foldRelease_, groups[g].release);
    }
    foldAngle_ = std::numbers::pi; // not known: the widest reading (FoldWatch)
    foldLeftOut_ = {};             // nor where the paper left out lay when it began
    if (folding()) beginStroke();
}

void EditSession::finishFold(bool letGo) {
    // applyScript has let the flap go (unless a step failed first); the groups have
    // nothing more to do.
    auto& groups = sim_.world().script.pins;
    if (letGo)
        for (std::size_t g = foldGroup_; g < groups.size(); ++g)
            if (groups[g].turnRate != 0.0) { // the carry: the flap
                foldWatch_.start(sim_.world().sheet, groups[g].vertices,
                                 groups[g].turnRate > 0.0 ? groups[g].axis : Vec3(-groups[g].axis),
                                 foldAngle_, sim_.world().time, std::move(foldLeftOut_));
                break;
            }
    auto& pinned = sim_.world().sheet.verts.pinned;
    bool held = false;
    for (std::size_t g = foldGroup_; g < groups.size(); ++g)
        for (Index i : groups[g].vertices)
            if (i >= 0 && i < sim_.world().sheet.verts.size()) {
                held = held || pinned[i];
                pinned[i] = 0;
            }
    if (foldGroup_ < groups.size())
        groups.erase(groups.begin() + static_cast<std::ptrdiff_t>(foldGroup_), groups.end());
    // What held the paper is gone. (Let go by the script, the step did this at its start,
    // as a sheet saved mid-fold and resumed without the editor does.)
    if (held) sim_.world().sheet.paper.wake();
    foldGroup_ = kNoFold;
    foldLeftOut_ = {}; // watched now, or not at all (a step failed)
    finished_ = endStroke(StrokeKind::Fold);
}

} // namespace pf

#pragma once

#include "World.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace pf {

struct SceneOptions {
    int resolution = 0; // vertices along the sheet's width; 0: the scene's own
    std::uint64_t seed = 1;
    double width = 0.210;  // metres, along x (A4 by default)
    double length = 0.297; // metres, along z
};

// Sheet sizes a scene accepts, metres.
inline constexpr double kMinSheetSide = 0.02;
inline constexpr double kMaxSheetSide = 2.0;

// The named scenes, defined once for the app, the tests and the benchmarks:
//   press    a sheet on the ground, pressed and dragged by a moving sphere (Fig. 13)
//   drape    pinned at two corners, falls under gravity; breaking off
//   compress two opposite edges pushed toward each other: the sheet buckles and creases
//   drop     a sheet tilted 45° falls onto the ground
//   fold     the near half is turned over onto the far one across the middle, held
//            pressed flat and let go, as the Fold tool folds: whether the crease holds
//            the fold
//   crumple-cycles  the rim gathered in to half the sheet's size and pulled out flat
//            again, kCrumpleCycles times: crease length against cycles (Gottesman et al.
//            2018), measured by CrumpleCycles.h
// Pins and arches follow the sheet's size. Returns nullopt for an unknown name, a
// resolution outside [kMinResolution, kMaxResolution] or a side outside the limits.
std::optional<World> makeScene(std::string_view name, const SceneOptions& options = {});
// The scene as the editor starts it: the user drives the tool (no scripted sphere; it
// has `toolRadius` and shows once the cursor is over the sheet), and gravity is
// integrated outside the filter (the solver lab's fix: the paper's step lets a hanging
// sheet fall at 0.4 % of g). An unknown name gives `press`.
World makeEditorScene(std::string_view name, const SceneOptions& options, double toolRadius);
const std::vector<std::string>& sceneNames();

// Makes the world's sheet of `material`: sets it in the parameters and scales the
// masses to its areal density.
void setMaterial(World& world, const Material& material);

// The crumple-cycles scene: each cycle gathers the rim in for kCrumpleGather seconds to
// kCrumpleFraction of its size, holds it kCrumpleSqueeze, pulls it out flat as long and
// holds it flat until the cycle's kCrumpleCycleSeconds are up.
inline constexpr int kCrumpleCycles = 10;
inline constexpr double kCrumpleCycleSeconds = 3.0;
inline constexpr double kCrumpleGather = 1.0;
inline constexpr double kCrumpleSqueeze = 0.25;
inline constexpr double kCrumpleFraction = 0.5;

inline constexpr int kMinResolution = 3;
inline constexpr int kMaxResolution = 200;

} // namespace pf

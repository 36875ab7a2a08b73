#pragma once

#include "World.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace pf {

struct SceneOptions {
    int resolution = 0; // vertices along the sheet's short side; 0: the scene's own
    std::uint64_t seed = 1;
};

// The named scenes, defined once for the app, the tests and the benchmarks:
//   press    a sheet on the ground, pressed and dragged by a moving sphere (Fig. 13)
//   drape    pinned at two corners, falls under gravity; breaking off
//   compress two opposite edges pushed toward each other: the sheet buckles and creases
//   drop     a sheet tilted 45° falls onto the ground
// Returns nullopt for an unknown name.
std::optional<World> makeScene(std::string_view name, const SceneOptions& options = {});
const std::vector<std::string>& sceneNames();

// Makes the world's sheet of `material`: sets it in the parameters and scales the
// masses to its areal density.
void setMaterial(World& world, const Material& material);

inline constexpr int kMinResolution = 3;
inline constexpr int kMaxResolution = 200;

} // namespace pf

#pragma once

#include "World.h"

#include <QJsonObject>

namespace pf::cli {

// The statistics `simulate --stats` and `replay --stats` print: the sheet's counts and
// strain, its state_hash (hex text: 64 bits do not survive JSON's doubles) and the speed.
QJsonObject statsJson(const World& world, double wallSeconds, long long steps);

} // namespace pf::cli

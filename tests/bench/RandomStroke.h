#pragma once

#include <QPoint>
#include <QRandomGenerator>
#include <functional>
#include <optional>

class QWidget;

namespace pf::bench {

// One push stroke as a user's mouse makes it, delivered synchronously to `view`: the
// button goes down at `start` (default: a random point near the centre), the cursor
// moves `moves` times 20 ms apart in a random direction, the button comes up. `stop`
// (if given) ends it early.
void randomStroke(QWidget* view, QRandomGenerator& rng, int moves,
                  const std::function<bool()>& stop = {}, std::optional<QPoint> start = {});

} // namespace pf::bench

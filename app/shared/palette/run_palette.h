#pragma once

#include <QColor>
#include <cstddef>
#include <string_view>
#include <vector>

namespace fooball::colours {

/// How many colours the palette holds: one per run of a run group (RunGroup::kMaxRuns) and one
/// per registered backend, whichever is more, all different and none the neutral grey.
int colourCount();

/// Run `runIndex`'s colour: in compare mode, in the readouts, in fooball-cli's compare chart.
/// Runs 0 to 7 keep the eight hues compare mode always had, far apart and light enough to read
/// on the near-black plot and on the black simulation view; past colourCount() they repeat.
QColor runColour(int runIndex);

/// The colour of `backend` in the Tools charts (capacity, trade-off, failure map): the colour of
/// its place in the registry, so the default compare runs (elastic, then box2d) match their
/// backends. An unknown name gets neutralColour().
QColor backendColour(std::string_view backend);

/// The palette for `count` colours (at least the eight run colours): what a registry of `count`
/// backends gets. Each colour past the eighth is the light, saturated one farthest from all before
/// it, from grey and from white, among those that read on the near-black plot.
std::vector<QColor> distinctColours(std::size_t count);

/// The chaos baseline's colour, and an unknown backend's: a grey no run and no backend has.
QColor neutralColour();

}  // namespace fooball::colours

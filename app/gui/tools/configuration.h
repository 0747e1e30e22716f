#pragma once

#include <QString>

#include "fooball/run_spec.h"
#include "fooball/scene.h"

namespace fooball::gui {

/// A point of a Tools chart: the scene it was measured on and the method that measured it.
struct Configuration {
  Scene scene;         ///< valid
  QString presetName;  ///< the preset the scene is, if it is one
  QString sourceName;  ///< how the title names the scene, e.g. "tunnelling sweep, v·h/r = 2.8"
  RunSpec spec;        ///< run 0's
};

}  // namespace fooball::gui

#pragma once

#include <QString>
#include <string_view>

namespace fooball::gui {

/// The engine's and registry's UTF-8 names and descriptions as Qt text.
inline QString fromView(std::string_view text) {
  return QString::fromUtf8(text.data(), static_cast<qsizetype>(text.size()));
}

}  // namespace fooball::gui

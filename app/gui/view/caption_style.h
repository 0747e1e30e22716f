#pragma once

#include <QRect>

namespace fooball::gui::caption_style {

/// The sizes the view's captions are laid out (view_captions.cpp) and painted
/// (view_painting.cpp) with.
constexpr int kBoxMargin = 8;              // px around each box
constexpr int kCaptionGap = 4;             // px between captions, and around their rows
constexpr int kPillPadding = 4;            // px around a caption's text
constexpr int kSwatchWidth = 20;           // px: a run's colour before its name
constexpr int kTemperatureBarWidth = 110;  // px: the speed scale's gradient
constexpr int kAccentWidth = 10;           // px: the bar left of the preset's caption

/// The preset caption's close button: a square at its top-right corner, one line tall.
inline QRect closeButtonOf(const QRect& caption, int size) {
  return QRect(caption.right() + 1 - size, caption.top(), size, size);
}

}  // namespace fooball::gui::caption_style

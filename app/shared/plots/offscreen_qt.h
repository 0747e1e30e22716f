#pragma once

#include <QtGlobal>
#include <memory>

class QApplication;

namespace fooball::plots {

/// A QApplication for drawing into images, made on first use: with the "offscreen" platform
/// unless QT_QPA_PLATFORM says otherwise, so charts render the same with or without a display
/// (over ssh, in CI). Reuses the application when the program already has one. Internal to
/// fooball_plots: this header is not part of its Qt-free interface.
class OffscreenQt {
 public:
  OffscreenQt();
  ~OffscreenQt();
  OffscreenQt(const OffscreenQt&) = delete;
  OffscreenQt& operator=(const OffscreenQt&) = delete;

 private:
  std::unique_ptr<QApplication> ownApplication_;
  QtMessageHandler previousHandler_ = nullptr;
};

}  // namespace fooball::plots

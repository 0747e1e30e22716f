#pragma once

#include <QFrame>

#include "run_controller.h"

class QLabel;

namespace fooball::gui {

/// The strip above the view in compare mode: which backends run, and how far they have
/// diverged — RMS and largest position difference over all balls, and the energy and momentum
/// differences. Same scene, same forces: any difference is the methods'.
class CompareReadout : public QFrame {
  Q_OBJECT

 public:
  explicit CompareReadout(QWidget* parent = nullptr);

  QString text() const;  ///< all figures as one line of plain text

 public slots:
  void showRuns(const QString& mainBackend, const QString& compareBackend);
  void showDivergence(const Divergence& divergence);

 private:
  QLabel* addTile(const QString& caption, const QString& toolTip);

  QLabel* runs_;
  QLabel* rms_;
  QLabel* max_;
  QLabel* energy_;
  QLabel* momentum_;
};

}  // namespace fooball::gui

#pragma once

#include <QWidget>
#include <cstddef>

#include "fooball/scene.h"

class QDoubleSpinBox;
class QLabel;
class QPushButton;

namespace fooball::gui {

/// Shows one ball and edits it: position, velocity, radius, mass and colour, or deletes it.
/// Every finished edit emits the whole ball; the owner applies it to every run and reports a
/// validation error back with showError(), leaving the ball as it was.
class BallInspector : public QWidget {
  Q_OBJECT

 public:
  explicit BallInspector(QWidget* parent = nullptr);

  std::size_t ballIndex() const { return index_; }
  /// The ball as the fields show it; a field the user left as it was keeps the exact value,
  /// not the rounded one it shows.
  BallDef editedBall() const;

 public slots:
  /// Shows ball `index`; the field being typed into keeps what the user typed unless
  /// `overwriteEdits` (after a refused edit: show what the ball really is).
  void showBall(std::size_t index, const BallDef& ball, bool overwriteEdits = false);
  void showError(const QString& message);

 signals:
  void ballEdited(std::size_t index, const BallDef& ball);
  void deleteRequested(std::size_t index);

 private:
  QDoubleSpinBox* addNumberField(double minimum, double maximum, const QString& suffix,
                                 const QString& toolTip);
  void emitEdit();
  void chooseColour();
  void showColour();

  std::size_t index_ = 0;
  BallDef ball_;
  QLabel* title_;
  QDoubleSpinBox* x_;
  QDoubleSpinBox* y_;
  QDoubleSpinBox* vx_;
  QDoubleSpinBox* vy_;
  QDoubleSpinBox* radius_;
  QDoubleSpinBox* mass_;
  QPushButton* colour_;
  QPushButton* delete_;
  QLabel* error_;
};

}  // namespace fooball::gui

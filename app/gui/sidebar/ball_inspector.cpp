#include "sidebar/ball_inspector.h"

#include <QColorDialog>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>

#include "fooball/scene.h"
#include "widgets/number_field_keys.h"

namespace fooball::gui {

namespace {

constexpr double kLimit = kMaxBoxSide;  // m, m/s: as far as any valid box reaches

/// The field's value, or `exact` while the field shows `exact` as it shows any value, rounded to
/// its decimals: an edit of one field leaves the others' values exactly as they were.
double valueOr(const QDoubleSpinBox* field, double exact) {
  return field->value() == field->valueFromText(field->textFromValue(exact)) ? exact
                                                                             : field->value();
}

}  // namespace

BallInspector::BallInspector(QWidget* parent)
    : QWidget(parent),
      title_(new QLabel),
      x_(addNumberField(-kLimit, kLimit, tr(" m"), tr("Centre x, metres from the left wall"))),
      y_(addNumberField(-kLimit, kLimit, tr(" m"), tr("Centre y, metres above the floor"))),
      vx_(addNumberField(-kLimit, kLimit, tr(" m/s"), tr("Velocity x in m/s (right is positive)"))),
      vy_(addNumberField(-kLimit, kLimit, tr(" m/s"), tr("Velocity y in m/s (up is positive)"))),
      radius_(addNumberField(1e-4, kLimit, tr(" m"), tr("Radius in metres (> 0)"))),
      mass_(addNumberField(1e-6, 1e12, tr(" kg"), tr("Mass in kilograms (> 0)"))),
      colour_(new QPushButton),
      delete_(new QPushButton(tr("Delete ball"))),
      error_(new QLabel) {
  QFont bold = title_->font();
  bold.setBold(true);
  title_->setFont(bold);
  colour_->setToolTip(tr("The ball's colour (drawing only)"));
  delete_->setToolTip(tr("Remove this ball from every run"));
  error_->setWordWrap(true);
  error_->setStyleSheet(QStringLiteral("color: #ff6b6b"));
  error_->setObjectName(QStringLiteral("inspectorError"));
  error_->hide();
  x_->setObjectName(QStringLiteral("inspectorX"));
  y_->setObjectName(QStringLiteral("inspectorY"));
  vx_->setObjectName(QStringLiteral("inspectorVx"));
  vy_->setObjectName(QStringLiteral("inspectorVy"));
  radius_->setObjectName(QStringLiteral("inspectorRadius"));
  mass_->setObjectName(QStringLiteral("inspectorMass"));
  delete_->setObjectName(QStringLiteral("inspectorDelete"));

  connect(colour_, &QPushButton::clicked, this, &BallInspector::chooseColour);
  connect(delete_, &QPushButton::clicked, this, [this] { emit deleteRequested(index_); });

  auto* form = new QFormLayout;
  form->setContentsMargins(0, 0, 0, 0);
  const auto pair = [](QWidget* a, QWidget* b) {
    auto* row = new QHBoxLayout;
    row->addWidget(a);
    row->addWidget(b);
    return row;
  };
  form->addRow(tr("Position:"), pair(x_, y_));
  form->addRow(tr("Velocity:"), pair(vx_, vy_));
  form->addRow(tr("Radius:"), radius_);
  form->addRow(tr("Mass:"), mass_);
  form->addRow(tr("Colour:"), colour_);

  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(title_);
  layout->addLayout(form);
  layout->addWidget(error_);
  layout->addWidget(delete_);
}

QDoubleSpinBox* BallInspector::addNumberField(double minimum, double maximum, const QString& suffix,
                                              const QString& toolTip) {
  auto* field = new QDoubleSpinBox;
  field->setRange(minimum, maximum);
  field->setDecimals(4);
  field->setSuffix(suffix);
  field->setToolTip(toolTip);
  field->setStepType(QAbstractSpinBox::AdaptiveDecimalStepType);
  field->setKeyboardTracking(false);
  field->setMinimumWidth(60);
  connect(field, &QDoubleSpinBox::editingFinished, this, &BallInspector::emitEdit);
  return field;
}

BallDef BallInspector::editedBall() const {
  BallDef ball = ball_;
  ball.position = {valueOr(x_, ball_.position.x), valueOr(y_, ball_.position.y)};
  ball.velocity = {valueOr(vx_, ball_.velocity.x), valueOr(vy_, ball_.velocity.y)};
  ball.radius = valueOr(radius_, ball_.radius);
  ball.mass = valueOr(mass_, ball_.mass);
  return ball;
}

void BallInspector::showBall(std::size_t index, const BallDef& ball, bool overwriteEdits) {
  const bool otherBall = index != index_;
  const bool keepEdits = !otherBall && !overwriteEdits;
  index_ = index;
  ball_ = ball;
  title_->setText(tr("Ball #%1").arg(index));
  const auto show = [keepEdits](QDoubleSpinBox* field, double value) {
    // A field the user is typing into keeps the text; one that merely has focus shows the ball
    // (the mass that followed a new radius, the position of a moving ball).
    if (keepEdits && field->hasFocus() && isBeingEdited(*field)) return;
    const QSignalBlocker blocker(field);
    field->setValue(value);
  };
  show(x_, ball.position.x);
  show(y_, ball.position.y);
  show(vx_, ball.velocity.x);
  show(vy_, ball.velocity.y);
  show(radius_, ball.radius);
  show(mass_, ball.mass);
  showColour();
  if (otherBall) error_->hide();
}

void BallInspector::showError(const QString& message) {
  error_->setText(message);
  error_->setVisible(!message.isEmpty());
}

void BallInspector::emitEdit() {
  const BallDef edited = editedBall();
  if (edited.position == ball_.position && edited.velocity == ball_.velocity &&
      edited.radius == ball_.radius && edited.mass == ball_.mass) {
    return;
  }
  error_->hide();
  emit ballEdited(index_, edited);
}

void BallInspector::chooseColour() {
  const QColor chosen =
      QColorDialog::getColor(QColor::fromRgb(ball_.color), this, tr("Ball colour"));
  if (!chosen.isValid()) return;
  BallDef edited = editedBall();
  edited.color = chosen.rgb() & 0xffffffu;
  emit ballEdited(index_, edited);
}

void BallInspector::showColour() {
  const QColor colour = QColor::fromRgb(ball_.color);
  colour_->setText(colour.name());
  colour_->setStyleSheet(QStringLiteral("QPushButton { background: %1; color: %2; }")
                             .arg(colour.name(), colour.lightnessF() > 0.55 ? "black" : "white"));
}

}  // namespace fooball::gui

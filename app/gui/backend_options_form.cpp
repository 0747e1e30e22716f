#include "backend_options_form.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QSpinBox>
#include <algorithm>
#include <climits>
#include <cmath>

#include "fooball/backend.h"

namespace fooball::gui {

namespace {

int toInt(double value) {
  return static_cast<int>(std::clamp(value, double(INT_MIN), double(INT_MAX)));
}

}  // namespace

BackendOptionsForm::BackendOptionsForm(QWidget* parent)
    : QWidget(parent), form_(new QFormLayout(this)) {
  form_->setContentsMargins(0, 0, 0, 0);
  form_->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
}

void BackendOptionsForm::showOptions(const Backend& backend) {
  while (form_->rowCount() > 0)
    form_->removeRow(0);

  for (const OptionSpec& spec : backend.options().specs()) {
    const QString name = QString::fromStdString(spec.name);
    const QString description = QString::fromStdString(spec.description);
    const double value = backend.options().value(spec.name);
    QWidget* field = nullptr;
    if (spec.integer && spec.min == 0.0 && spec.max == 1.0) {
      auto* box = new QCheckBox;
      box->setChecked(value != 0.0);
      connect(box, &QCheckBox::toggled, this,
              [this, name](bool on) { emit optionChanged(name, on ? 1.0 : 0.0); });
      field = box;
    } else if (spec.integer) {
      auto* spin = new QSpinBox;
      spin->setRange(toInt(spec.min), toInt(spec.max));
      spin->setValue(toInt(value));
      spin->setKeyboardTracking(false);
      connect(spin, &QSpinBox::valueChanged, this,
              [this, name](int chosen) { emit optionChanged(name, chosen); });
      field = spin;
    } else {
      auto* spin = new QDoubleSpinBox;
      // Enough decimals to show the smallest allowed value.
      const int decimals =
          spec.min > 0.0 ? 2 - static_cast<int>(std::floor(std::log10(spec.min))) : 4;
      spin->setDecimals(std::clamp(decimals, 3, 10));
      spin->setRange(spec.min, spec.max);
      spin->setStepType(QAbstractSpinBox::AdaptiveDecimalStepType);
      spin->setValue(value);
      spin->setKeyboardTracking(false);
      connect(spin, &QDoubleSpinBox::valueChanged, this,
              [this, name](double chosen) { emit optionChanged(name, chosen); });
      field = spin;
    }
    field->setObjectName(QStringLiteral("option_") + name);
    field->setToolTip(description);
    auto* label = new QLabel(name + QLatin1Char(':'));
    label->setToolTip(description);
    label->setBuddy(field);
    form_->addRow(label, field);
  }
  if (form_->rowCount() == 0) {
    auto* none = new QLabel(tr("no options"));
    none->setEnabled(false);
    none->setToolTip(tr("This backend has no settings of its own."));
    form_->addRow(none);
  }
}

}  // namespace fooball::gui

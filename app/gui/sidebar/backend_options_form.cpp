#include "sidebar/backend_options_form.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QRegularExpression>
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

/// "velocity_iterations" → "Velocity iterations": the option key (in the tooltip) as words.
QString humanLabel(const QString& key) {
  QString label = key;
  label.replace(QLatin1Char('_'), QLatin1Char(' '));
  if (!label.isEmpty()) label[0] = label[0].toUpper();
  return label;
}

/// A real-valued option field that shows six significant digits, in exponent form where the
/// value needs it ("1e-06" s, not "0.0000"), and reads either form back.
class RealOptionBox : public QDoubleSpinBox {
 public:
  RealOptionBox() {
    // QDoubleSpinBox rounds every value to its decimals: enough for the smallest doubles.
    setDecimals(323);
  }

 protected:
  QString textFromValue(double value) const override { return locale().toString(value, 'g', 6); }
  double valueFromText(const QString& text) const override {
    return locale().toDouble(text.trimmed());
  }
  QValidator::State validate(QString& text, int&) const override {
    const QString trimmed = text.trimmed();
    bool ok = false;
    const double value = locale().toDouble(trimmed, &ok);
    if (ok)
      return value >= minimum() && value <= maximum() ? QValidator::Acceptable
                                                      : QValidator::Intermediate;
    // Part of a number still being typed: "1e-", "-", "0.".
    static const QRegularExpression partial(
        QStringLiteral("^[-+]?[0-9]*[.,]?[0-9]*([eE][-+]?[0-9]*)?$"));
    return partial.match(trimmed).hasMatch() ? QValidator::Intermediate : QValidator::Invalid;
  }
};

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
    if (!spec.choices.empty()) {
      // Named values (an engine's releases): the value is the chosen one's index.
      auto* box = new QComboBox;
      for (const std::string& choice : spec.choices)
        box->addItem(QString::fromStdString(choice));
      box->setCurrentIndex(toInt(value));
      connect(box, &QComboBox::currentIndexChanged, this,
              [this, name](int chosen) { emit optionChanged(name, chosen); });
      field = box;
    } else if (spec.integer && spec.min == 0.0 && spec.max == 1.0) {
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
      auto* spin = new RealOptionBox;
      spin->setRange(spec.min, spec.max);
      spin->setStepType(QAbstractSpinBox::AdaptiveDecimalStepType);
      spin->setValue(value);
      spin->setKeyboardTracking(false);
      connect(spin, &QDoubleSpinBox::valueChanged, this,
              [this, name](double chosen) { emit optionChanged(name, chosen); });
      field = spin;
    }
    field->setObjectName(QStringLiteral("option_") + name);
    const QString toolTip = tr("%1 (option %2)").arg(description, name);
    field->setToolTip(toolTip);
    auto* label = new QLabel(humanLabel(name) + QLatin1Char(':'));
    label->setToolTip(toolTip);
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

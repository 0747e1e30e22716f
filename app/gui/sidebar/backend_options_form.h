#pragma once

#include <QWidget>

class QFormLayout;

namespace fooball {
class Backend;
}

namespace fooball::gui {

/// The options of one backend as a form, generated from its OptionSpecs: a drop-down list for
/// named values (OptionSpec::choices), a check box for 0/1 options, a spin box for other whole
/// numbers, a double spin box otherwise. Each field shows
/// the option's description as its tooltip.
class BackendOptionsForm : public QWidget {
  Q_OBJECT

 public:
  explicit BackendOptionsForm(QWidget* parent = nullptr);

  /// Rebuilds the fields for `backend`'s options, showing their current values.
  void showOptions(const Backend& backend);

 signals:
  void optionChanged(const QString& name, double value);

 private:
  QFormLayout* form_;
};

}  // namespace fooball::gui

#pragma once

#include <QGroupBox>
#include <QString>
#include <vector>

#include "view/simulation_view.h"

class QButtonGroup;
class QCheckBox;
class QComboBox;
class QLabel;
class QPushButton;
class QToolButton;
class QVBoxLayout;

namespace fooball {
class RunGroup;
}

namespace fooball::gui {

class BackendOptionsForm;

/// The sidebar's "Runs" group: one row per run of the run group — its colour, its backend and
/// its options — with Add run and a remove button per run, the chaos baseline's check box and
/// the compare layout. Run 0 is the reference the others are measured from. It only reports
/// what the user chose; showRuns() syncs it back.
class RunListEditor : public QGroupBox {
  Q_OBJECT

 public:
  explicit RunListEditor(QWidget* parent = nullptr);

  int rowCount() const { return static_cast<int>(rows_.size()); }
  QComboBox* backendBox(int run) const { return rows_.at(std::size_t(run)).backend; }
  BackendOptionsForm* optionsForm(int run) const { return rows_.at(std::size_t(run)).options; }
  QToolButton* removeButton(int run) const { return rows_.at(std::size_t(run)).remove; }
  QPushButton* addButton() const { return add_; }
  /// The backend Add run adds (a registered backend no run uses yet, until the user picks).
  QComboBox* newRunBackendBox() const { return newRunBackend_; }
  QCheckBox* baselineBox() const { return baseline_; }

 public slots:
  /// One row per run, showing each run's backend and options as they are now.
  void showRuns(const RunGroup& group);
  void showCompareLayout(CompareLayout layout);

 signals:
  void backendChosen(int run, const QString& name);
  void optionChanged(int run, const QString& name, double value);
  /// A new run with the backend of `name`.
  void addRunRequested(const QString& name);
  void removeRunRequested(int run);
  void baselineToggled(bool on);
  void compareLayoutChosen(CompareLayout layout);

 private:
  struct Row {
    QWidget* frame;
    QLabel* title;
    QComboBox* backend;
    QToolButton* remove;
    BackendOptionsForm* options;
  };
  void addRow();

  QVBoxLayout* rowsLayout_;
  std::vector<Row> rows_;
  QPushButton* add_;
  QComboBox* newRunBackend_;
  QCheckBox* baseline_;
  QWidget* compareRow_;
  QButtonGroup* compareLayout_;
};

}  // namespace fooball::gui

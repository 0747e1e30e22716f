#include "sidebar/run_list_editor.h"

#include <QButtonGroup>
#include <QCheckBox>
#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QRadioButton>
#include <QToolButton>
#include <QVBoxLayout>

#include "fooball/run_group.h"
#include "registry.h"
#include "run_palette.h"
#include "sidebar/backend_options_form.h"
#include "widgets/view_text.h"

namespace fooball::gui {

namespace {

/// The first registered backend no run uses yet, so Add run compares a new method; the first
/// backend when every one is in use (then the user picks other options).
QString unusedBackend(const RunGroup& group) {
  for (const BackendInfo& info : registeredBackends()) {
    bool used = false;
    for (std::size_t i = 0; i < group.runCount(); ++i)
      used = used || group.spec(i).backend == info.name;
    if (!used) return fromView(info.name);
  }
  return fromView(registeredBackends().front().name);
}

/// Every registered backend, each with its description as tooltip.
void addBackends(QComboBox* box) {
  for (const BackendInfo& info : registeredBackends()) {
    box->addItem(fromView(info.name));
    box->setItemData(box->count() - 1, fromView(info.description), Qt::ToolTipRole);
  }
}

}  // namespace

RunListEditor::RunListEditor(QWidget* parent) : QGroupBox(tr("Runs"), parent) {
  setObjectName(QStringLiteral("runList"));
  setToolTip(
      tr("Every run steps the same scene in lockstep: the same start, forces and edits. Run 0 "
         "is the reference; each other run's divergence is measured from it."));
  auto* layout = new QVBoxLayout(this);
  rowsLayout_ = new QVBoxLayout;
  rowsLayout_->setSpacing(6);
  layout->addLayout(rowsLayout_);

  add_ = new QPushButton(tr("Add run"));
  add_->setObjectName(QStringLiteral("addRunButton"));
  add_->setToolTip(
      tr("Compare another method (up to %1 runs). Every run restarts from run 0's state now, "
         "so that all start identical; the charts keep their history.")
          .arg(RunGroup::kMaxRuns));
  newRunBackend_ = new QComboBox;
  newRunBackend_->setObjectName(QStringLiteral("newRunBackendBox"));
  newRunBackend_->setToolTip(tr("The backend of the run Add run adds"));
  addBackends(newRunBackend_);
  connect(add_, &QPushButton::clicked, this,
          [this] { emit addRunRequested(newRunBackend_->currentText()); });
  auto* addRow = new QHBoxLayout;
  addRow->addWidget(add_);
  addRow->addWidget(newRunBackend_, 1);
  layout->addLayout(addRow);

  baseline_ = new QCheckBox(tr("Chaos baseline"));
  baseline_->setObjectName(QStringLiteral("baselineBox"));
  baseline_->setToolTip(
      tr("A hidden copy of run 0 with every ball moved %1 m. Its divergence (grey) shows how "
         "fast any difference grows in this scene: a run that departs no faster is as close "
         "to run 0 as chaos allows.")
          .arg(RunGroup::kBaselineDisplacement));
  connect(baseline_, &QCheckBox::toggled, this, &RunListEditor::baselineToggled);
  layout->addWidget(baseline_);

  compareRow_ = new QWidget;
  auto* compareLayout = new QHBoxLayout(compareRow_);
  compareLayout->setContentsMargins(0, 0, 0, 0);
  compareLayout_ = new QButtonGroup(this);
  const auto addRadio = [&](CompareLayout id, const QString& text, const QString& objectName,
                            const QString& toolTip) {
    auto* button = new QRadioButton(text);
    button->setObjectName(objectName);
    button->setToolTip(toolTip);
    compareLayout_->addButton(button, int(id));
    compareLayout->addWidget(button);
  };
  addRadio(CompareLayout::Overlay, tr("Overlay"), QStringLiteral("overlayRadio"),
           tr("One box: run 0 filled, the other runs as outlines in their colours"));
  addRadio(CompareLayout::SideBySide, tr("Side by side"), QStringLiteral("sidebysideRadio"),
           tr("A labelled box per run"));
  connect(compareLayout_, &QButtonGroup::idClicked, this,
          [this](int id) { emit compareLayoutChosen(static_cast<CompareLayout>(id)); });
  layout->addWidget(compareRow_);
}

void RunListEditor::addRow() {
  const int run = rowCount();
  Row row;
  row.frame = new QWidget;
  auto* layout = new QVBoxLayout(row.frame);
  layout->setContentsMargins(0, 0, 0, 0);
  auto* header = new QHBoxLayout;
  row.title = new QLabel;
  row.backend = new QComboBox;
  row.backend->setObjectName(QStringLiteral("runBackendBox%1").arg(run));
  addBackends(row.backend);
  row.backend->setToolTip(
      tr("The physics method; switching continues from the same positions and velocities"));
  row.title->setBuddy(row.backend);
  row.remove = new QToolButton;
  row.remove->setText(QStringLiteral("✕"));
  row.remove->setObjectName(QStringLiteral("removeRunButton%1").arg(run));
  row.remove->setToolTip(tr("Remove this run; the others carry on"));
  header->addWidget(row.title);
  header->addWidget(row.backend, 1);
  header->addWidget(row.remove);
  layout->addLayout(header);
  row.options = new BackendOptionsForm;
  layout->addWidget(row.options);
  connect(row.backend, &QComboBox::activated, this, [this, run, box = row.backend](int index) {
    emit backendChosen(run, box->itemText(index));
  });
  connect(row.remove, &QToolButton::clicked, this, [this, run] { emit removeRunRequested(run); });
  connect(row.options, &BackendOptionsForm::optionChanged, this,
          [this, run](const QString& name, double value) { emit optionChanged(run, name, value); });
  rowsLayout_->addWidget(row.frame);
  rows_.push_back(row);
}

void RunListEditor::showRuns(const RunGroup& group) {
  const int runs = static_cast<int>(group.runCount());
  while (rowCount() < runs)
    addRow();
  while (rowCount() > runs) {
    delete rows_.back().frame;
    rows_.pop_back();
  }
  for (int run = 0; run < runs; ++run) {
    const Row& row = rows_[std::size_t(run)];
    const QString colour = colours::runColour(run).name();
    row.title->setText(QStringLiteral("<span style='color:%1'>●</span> %2")
                           .arg(colour, run == 0 ? tr("Run 0") : tr("Run %1").arg(run)));
    row.title->setToolTip(run == 0 ? tr("The reference run") : tr("Compared with run 0"));
    row.backend->setCurrentText(QString::fromStdString(group.spec(std::size_t(run)).backend));
    row.remove->setVisible(runs > 1);
    row.options->showOptions(group.run(std::size_t(run)).backend());
  }
  add_->setEnabled(group.runCount() < RunGroup::kMaxRuns);
  newRunBackend_->setEnabled(add_->isEnabled());
  newRunBackend_->setCurrentText(unusedBackend(group));
  const QSignalBlocker blocker(baseline_);
  baseline_->setChecked(group.hasBaseline());
  compareRow_->setVisible(runs > 1);
}

void RunListEditor::showCompareLayout(CompareLayout layout) {
  if (QAbstractButton* button = compareLayout_->button(int(layout))) button->setChecked(true);
}

}  // namespace fooball::gui

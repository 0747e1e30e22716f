#include "widgets/checklist.h"

#include "widgets/view_text.h"

namespace fooball::gui {

QListWidget* newChecklist(const QStringList& names, const QStringList& toolTips,
                          const QString& toolTip) {
  auto* list = new QListWidget;
  list->setToolTip(toolTip);
  for (qsizetype i = 0; i < names.size(); ++i) {
    auto* item = new QListWidgetItem(names[i], list);
    item->setFlags(item->flags() | Qt::ItemIsUserCheckable);
    item->setCheckState(Qt::Checked);
    item->setToolTip(toolTips.value(i));
  }
  list->setMaximumHeight(list->sizeHintForRow(0) * (list->count() + 1));
  return list;
}

QStringList checkedNames(const QListWidget& list) {
  QStringList names;
  for (int row = 0; row < list.count(); ++row) {
    if (list.item(row)->checkState() == Qt::Checked) names.append(list.item(row)->text());
  }
  return names;
}

QListWidget* newBackendChecklist(const QString& toolTip) {
  QStringList names;
  QStringList descriptions;
  for (const BackendInfo& info : registeredBackends()) {
    names.append(fromView(info.name));
    descriptions.append(fromView(info.description));
  }
  return newChecklist(names, descriptions, toolTip);
}

std::vector<BackendInfo> checkedBackends(const QListWidget& list) {
  const QStringList names = checkedNames(list);
  std::vector<BackendInfo> chosen;
  for (const BackendInfo& info : registeredBackends()) {
    if (names.contains(fromView(info.name))) chosen.push_back(info);
  }
  return chosen;
}

}  // namespace fooball::gui

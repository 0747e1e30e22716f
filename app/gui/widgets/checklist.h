#pragma once

#include <QListWidget>
#include <QString>
#include <QStringList>
#include <vector>

#include "registry.h"

namespace fooball::gui {

/// A list of names to check, all checked at first, each with `toolTips` (same length) as its
/// tooltip; no taller than its rows.
QListWidget* newChecklist(const QStringList& names, const QStringList& toolTips,
                          const QString& toolTip);
/// The names checked, in the list's order.
QStringList checkedNames(const QListWidget& list);

/// Every registered backend, with its description.
QListWidget* newBackendChecklist(const QString& toolTip);
/// The backends checked, in the registry's order.
std::vector<BackendInfo> checkedBackends(const QListWidget& list);

}  // namespace fooball::gui

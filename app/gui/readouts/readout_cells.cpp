#include "readouts/readout_cells.h"

#include <QLabel>

#include "readable_number.h"

namespace fooball::gui {

QString figure(double value) {
  return QString::fromStdString(text::figureText(value));
}

QString noFigure() {
  return QString::fromUtf8(text::kNoFigure.data(), qsizetype(text::kNoFigure.size()));
}

QLabel* readoutCell(const QString& text, const char* role, const QString& toolTip) {
  auto* label = new QLabel(text);
  label->setProperty("role", role);
  label->setToolTip(toolTip);
  return label;
}

}  // namespace fooball::gui

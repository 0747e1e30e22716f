#include "widgets/dark_theme.h"

#include <QAbstractAxis>
#include <QApplication>
#include <QChart>
#include <QLegend>
#include <QPainter>
#include <QProxyStyle>
#include <QStyleFactory>
#include <QStyleOption>
#include <QToolTip>
#include <algorithm>
#include <cmath>

#include "charts/toggle_icon.h"

namespace fooball::gui {
namespace {

// The box's surround and the charts' background are #16171c; the window around them one step
// lighter, so docks and panels read as frames around the box.
const QColor kWindow{0x20, 0x22, 0x29};
const QColor kBase{0x16, 0x17, 0x1c};  ///< fields, lists, tables: the charts' background
const QColor kAlternateBase{0x1c, 0x1e, 0x25};
const QColor kButton{0x2b, 0x2e, 0x38};
const QColor kText{0xe6, 0xe7, 0xeb};          ///< 14:1 on kWindow
const QColor kDisabledText{0x86, 0x8b, 0x98};  ///< 4.8:1 on kWindow: dim, still readable
const QColor kHighlight{0x2f, 0x6f, 0xd0};
const QColor kLink{0x7c, 0xb7, 0xff};

/// sRGB channel to linear light, as WCAG defines relative luminance.
double linear(double channel) {
  return channel <= 0.04045 ? channel / 12.92 : std::pow((channel + 0.055) / 1.055, 2.4);
}

double luminance(const QColor& colour) {
  return 0.2126 * linear(colour.redF()) + 0.7152 * linear(colour.greenF()) +
         0.0722 * linear(colour.blueF());
}

/// Fusion, with check boxes and radio buttons of the app's own (paintCheckBox): Fusion outlines
/// them in the window colour made darker, which on a dark window leaves an empty box invisible.
class DarkStyle : public QProxyStyle {
 public:
  DarkStyle() : QProxyStyle(QStyleFactory::create(QStringLiteral("Fusion"))) {}

  void drawPrimitive(PrimitiveElement element, const QStyleOption* option, QPainter* painter,
                     const QWidget* widget) const override {
    const bool enabled = option->state.testFlag(State_Enabled);
    switch (element) {
      case PE_IndicatorCheckBox:
      case PE_IndicatorItemViewItemCheck: {
        Qt::CheckState state = Qt::Unchecked;
        if (option->state.testFlag(State_On)) state = Qt::Checked;
        if (option->state.testFlag(State_NoChange)) state = Qt::PartiallyChecked;
        paintCheckBox(*painter, QRectF(option->rect).adjusted(0.5, 0.5, -0.5, -0.5), state,
                      enabled);
        return;
      }
      case PE_IndicatorRadioButton:
        paintRadioButton(*painter, QRectF(option->rect).adjusted(0.5, 0.5, -0.5, -0.5),
                         option->state.testFlag(State_On), enabled);
        return;
      default:
        QProxyStyle::drawPrimitive(element, option, painter, widget);
    }
  }
};

}  // namespace

QPalette darkPalette() {
  QPalette palette;
  palette.setColor(QPalette::Window, kWindow);
  palette.setColor(QPalette::WindowText, kText);
  palette.setColor(QPalette::Base, kBase);
  palette.setColor(QPalette::AlternateBase, kAlternateBase);
  palette.setColor(QPalette::Text, kText);
  palette.setColor(QPalette::PlaceholderText, kDisabledText);
  palette.setColor(QPalette::Button, kButton);
  palette.setColor(QPalette::ButtonText, kText);
  palette.setColor(QPalette::BrightText, Qt::white);
  palette.setColor(QPalette::ToolTipBase, kButton);
  palette.setColor(QPalette::ToolTipText, kText);
  palette.setColor(QPalette::Highlight, kHighlight);
  palette.setColor(QPalette::HighlightedText, Qt::white);
  palette.setColor(QPalette::Link, kLink);
  palette.setColor(QPalette::LinkVisited, kLink);
  // Fusion shades bevels, frames and handles from these.
  palette.setColor(QPalette::Light, kButton.lighter(150));
  palette.setColor(QPalette::Midlight, kButton.lighter(120));
  palette.setColor(QPalette::Mid, kButton.darker(130));
  palette.setColor(QPalette::Dark, kBase.darker(130));
  palette.setColor(QPalette::Shadow, Qt::black);
  for (const QPalette::ColorRole role :
       {QPalette::WindowText, QPalette::Text, QPalette::ButtonText, QPalette::HighlightedText}) {
    palette.setColor(QPalette::Disabled, role, kDisabledText);
  }
  palette.setColor(QPalette::Disabled, QPalette::Button, kWindow);
  palette.setColor(QPalette::Disabled, QPalette::Base, kWindow);
  palette.setColor(QPalette::Disabled, QPalette::Highlight, kButton);
  return palette;
}

void applyDarkTheme(QApplication& app) {
  app.setStyle(new DarkStyle);  // the application owns its style
  const QPalette palette = darkPalette();
  QApplication::setPalette(palette);
  QToolTip::setPalette(palette);
}

void styleChartDark(QChart& chart) {
  const QColor background(0x16, 0x17, 0x1c);
  const QColor plotArea(0x05, 0x05, 0x07);
  const QColor text(0xe6, 0xe7, 0xeb);
  const QColor label(0xb4, 0xb7, 0xc0);
  const QColor grid(0x2c, 0x2e, 0x36);
  chart.setBackgroundBrush(background);
  chart.setPlotAreaBackgroundBrush(plotArea);
  chart.setPlotAreaBackgroundVisible(true);
  chart.setTitleBrush(text);
  chart.legend()->setLabelColor(label);
  for (QAbstractAxis* axis : chart.axes()) {
    axis->setLabelsColor(label);
    axis->setTitleBrush(text);
    axis->setGridLineColor(grid);
    axis->setMinorGridLineColor(grid);
    axis->setLinePenColor(label);
  }
}

double contrastRatio(const QColor& a, const QColor& b) {
  const double lighter = std::max(luminance(a), luminance(b));
  const double darker = std::min(luminance(a), luminance(b));
  return (lighter + 0.05) / (darker + 0.05);
}

}  // namespace fooball::gui

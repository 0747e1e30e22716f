// One dark theme throughout: the palette applyDarkTheme() sets at startup is dark with readable
// text in every role, and the main window, its menus, its docks, the dialogs (benchmark, help,
// file) and their widgets all draw with it.

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QFileDialog>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QRadioButton>
#include <QStyle>
#include <QTimer>
#include <QToolTip>
#include <functional>
#include <vector>

#include "gui_fixture.h"
#include "tools/benchmark_dialog.h"
#include "widgets/dark_theme.h"
#include "window/help_dialogs.h"

namespace fooball::gui::testing {
namespace {

double lightness(const QColor& colour) {
  return colour.lightnessF();
}

/// Dark behind, light in front, 4.5 : 1 at least (WCAG AA for body text), for the roles
/// that carry text.
void expectDarkAndReadable(const QWidget& widget, const std::string& where) {
  const QPalette palette = widget.palette();
  const std::string name =
      where + " / " + widget.metaObject()->className() + " " + widget.objectName().toStdString();
  EXPECT_LT(lightness(palette.color(QPalette::Window)), 0.25) << name;
  EXPECT_LT(lightness(palette.color(QPalette::Base)), 0.25) << name;
  for (const auto& [text, background] : {std::pair{QPalette::WindowText, QPalette::Window},
                                         std::pair{QPalette::Text, QPalette::Base},
                                         std::pair{QPalette::ButtonText, QPalette::Button}}) {
    EXPECT_GE(contrastRatio(palette.color(text), palette.color(background)), 4.5)
        << name << " role " << int(text);
  }
}

void expectAllDark(const QWidget& top, const std::string& where) {
  expectDarkAndReadable(top, where);
  for (const QWidget* child : top.findChildren<QWidget*>())
    expectDarkAndReadable(*child, where);
}

class Theme : public GuiTest {
 protected:
  void SetUp() override { applyDarkTheme(*qApp); }
};

TEST(DarkTheme, ContrastRatioIsWcags) {
  EXPECT_NEAR(contrastRatio(Qt::black, Qt::white), 21.0, 1e-9);
  EXPECT_NEAR(contrastRatio(Qt::white, Qt::black), 21.0, 1e-9);
  EXPECT_NEAR(contrastRatio(QColor(0x77, 0x77, 0x77), Qt::white), 4.48, 0.01);
}

TEST(DarkTheme, EveryTextRoleIsReadableActiveAndDisabled) {
  const QPalette palette = darkPalette();
  const std::vector<std::pair<QPalette::ColorRole, QPalette::ColorRole>> pairs{
      {QPalette::WindowText, QPalette::Window},
      {QPalette::Text, QPalette::Base},
      {QPalette::Text, QPalette::AlternateBase},
      {QPalette::ButtonText, QPalette::Button},
      {QPalette::ToolTipText, QPalette::ToolTipBase},
      {QPalette::HighlightedText, QPalette::Highlight},
      {QPalette::PlaceholderText, QPalette::Base},
      {QPalette::Link, QPalette::Base}};
  for (const auto& [text, background] : pairs) {
    EXPECT_GE(contrastRatio(palette.color(QPalette::Active, text),
                            palette.color(QPalette::Active, background)),
              4.5)
        << "roles " << int(text) << " on " << int(background);
  }
  for (const QPalette::ColorRole text :
       {QPalette::WindowText, QPalette::Text, QPalette::ButtonText}) {
    EXPECT_GE(contrastRatio(palette.color(QPalette::Disabled, text),
                            palette.color(QPalette::Disabled, QPalette::Window)),
              4.5)
        << "disabled role " << int(text);
  }
  EXPECT_LT(lightness(palette.color(QPalette::Window)), 0.2);
}

TEST_F(Theme, TooltipsAreDarkAndReadable) {
  const QPalette tips = QToolTip::palette();
  EXPECT_LT(lightness(tips.color(QPalette::ToolTipBase)), 0.25);
  EXPECT_GE(contrastRatio(tips.color(QPalette::ToolTipText), tips.color(QPalette::ToolTipBase)),
            4.5);
}

TEST_F(Theme, MainWindowMenusAndDocksAreDark) {
  open(stillBalls(), "elastic", {"exact", "box2d"});
  expectAllDark(*window, "main window");
  for (QAction* action : window->menuBar()->actions()) {
    ASSERT_NE(action->menu(), nullptr) << action->text().toStdString();
    expectAllDark(*action->menu(), action->text().toStdString());
  }
}

/// Pixels of `widget` as drawn that stand out from its window colour by 3 : 1 at least (the least
/// contrast for a control's outline).
int visiblePixels(QWidget& widget) {
  const QImage image = widget.grab().toImage();
  const QColor window = widget.palette().color(QPalette::Window);
  int visible = 0;
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x)
      visible += contrastRatio(image.pixelColor(x, y), window) >= 3.0 ? 1 : 0;
  }
  return visible;
}

TEST_F(Theme, UncheckedBoxesAndRadioButtonsShowOnTheDarkWindow) {
  // Fusion outlines an indicator in the window colour made darker: on a dark window an empty
  // check box or radio button was all but invisible.
  open(stillBalls());
  for (const bool checked : {false, true}) {
    QCheckBox box;
    box.setChecked(checked);
    QRadioButton radio;
    radio.setChecked(checked);
    for (QWidget* widget : std::initializer_list<QWidget*>{&box, &radio}) {
      widget->resize(widget->sizeHint());
      // The indicator alone (no text): an outline of about 4 × 12 px at least.
      EXPECT_GT(visiblePixels(*widget), 30)
          << widget->metaObject()->className() << (checked ? " checked" : " unchecked");
    }
  }
}

TEST_F(Theme, DialogsAreDark) {
  open(stillBalls());
  BenchmarkDialog benchmark(window.get());
  benchmark.show();
  expectAllDark(benchmark, "benchmark");

  QFileDialog files(window.get());
  files.setOption(QFileDialog::DontUseNativeDialog);
  files.show();
  expectAllDark(files, "file dialog");
  files.close();

  // The help dialogs are modal: look at each once it is up, then close it.
  const std::vector<std::function<void(QWidget*)>> helpPages{
      showAbout, [this](QWidget* parent) { showMouseAndKeys(parent, *window->menuBar()); },
      showReadingTheCharts};
  for (const auto& show : helpPages) {
    bool looked = false;
    QTimer poll;  // until the dialog is up, however slow the machine
    poll.setInterval(10);
    QObject::connect(&poll, &QTimer::timeout, [&] {
      QWidget* dialog = QApplication::activeModalWidget();
      if (dialog == nullptr) return;
      poll.stop();
      expectAllDark(*dialog, "help");
      looked = true;
      dialog->close();
    });
    poll.start();
    show(window.get());
    EXPECT_TRUE(looked);
  }
}

}  // namespace
}  // namespace fooball::gui::testing

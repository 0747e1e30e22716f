#include <QFileInfo>
#include <QMenuBar>
#include <QRegularExpression>
#include <QUrl>

#include "gui_fixture.h"
#include "window/help_dialogs.h"

namespace fooball::gui::testing {
namespace {

class Help : public GuiTest {};

TEST_F(Help, EveryDocLinkOpensAFileThatExists) {
  const QString text = readingTheChartsText();
  const QRegularExpression link(QStringLiteral("href=\"([^\"]+)\""));
  int links = 0;
  for (const QRegularExpressionMatch& match : link.globalMatch(text)) {
    const QUrl url(match.captured(1));
    ASSERT_TRUE(url.isLocalFile()) << match.captured(1).toStdString();
    EXPECT_TRUE(QFileInfo(url.toLocalFile()).isFile()) << url.toLocalFile().toStdString();
    ++links;
  }
  EXPECT_GE(links, 3) << "accuracy.md twice and the scene format";
  EXPECT_TRUE(text.contains(QStringLiteral("scene-format.md")));
  EXPECT_TRUE(QFileInfo(docFile(QStringLiteral("accuracy.md"))).isFile());
}

TEST_F(Help, MouseAndKeysListsEveryShortcutOfTheMenus) {
  open(stillBalls());
  const QString text = mouseAndKeysText(*window->menuBar());
  for (const char* keys : {"Ctrl+3", "Ctrl+O", "Ctrl+S", "Ctrl+E", "Ctrl+Shift+E", "Space",
                           "Ctrl+Backspace", "Ctrl+Shift+R"}) {
    EXPECT_TRUE(text.contains(QString::fromLatin1(keys))) << keys;
  }
  EXPECT_TRUE(text.contains(QStringLiteral("<b>.</b>")));
  EXPECT_TRUE(text.contains(QStringLiteral("<b>,</b>")));
  EXPECT_TRUE(text.contains(QStringLiteral("Timeline")));
  EXPECT_TRUE(text.contains(QStringLiteral("under the cursor"))) << "the slingshot's aim";
  // Every shortcut any action of the menus has, as that action has it now.
  for (QAction* menu : window->menuBar()->actions()) {
    for (QAction* action : menu->menu()->actions()) {
      for (const QKeySequence& shortcut : action->shortcuts()) {
        EXPECT_TRUE(text.contains(shortcut.toString(QKeySequence::NativeText).toHtmlEscaped()))
            << action->text().toStdString();
      }
    }
  }
}

}  // namespace
}  // namespace fooball::gui::testing

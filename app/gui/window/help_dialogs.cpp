#include "window/help_dialogs.h"

#include <QAction>
#include <QCoreApplication>
#include <QDir>
#include <QKeySequence>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QObject>
#include <QUrl>

#include "fooball/version.h"
#include "registry.h"
#include "source_doc_dir.h"
#include "widgets/view_text.h"

namespace fooball::gui {

void showAbout(QWidget* parent) {
  QMessageBox::about(
      parent, QObject::tr("About FooBall"),
      QObject::tr(
          "<h3>FooBall %2</h3><p>Bouncing balls on interchangeable physics backends. Run the same "
          "scene on two methods side by side and watch what each does to momentum and "
          "energy.</p><p>Grown from a Year 11 Java Swing project; rebuilt in C++20 and Qt %1.</p>")
          .arg(QString::fromLatin1(qVersion()), fromView(kVersion)));
}

QString docFile(const QString& name) {
  const QDir installed(QCoreApplication::applicationDirPath() +
                       QStringLiteral("/" FOOBALL_INSTALLED_DOC_DIR));
  if (installed.exists(name)) return installed.filePath(name);
  return QDir(QString::fromUtf8(checkout::kSourceDocDir)).filePath(name);
}

namespace {

/// A link to `name` in the docs, reading "docs/name" (+ "#anchor").
QString docLink(const QString& name, const QString& anchor = QString()) {
  QUrl url = QUrl::fromLocalFile(docFile(name));
  if (!anchor.isEmpty()) url.setFragment(anchor);
  return QStringLiteral("<a href=\"%1\">docs/%2</a>").arg(url.toString(), name);
}

QString row(const QString& keys, const QString& what) {
  return QStringLiteral("<tr><td><b>%1</b></td><td>%2</td></tr>").arg(keys, what);
}

/// Every action of `menu` and its submenus with a shortcut, as rows "Ctrl+O — Open scene…".
void addShortcutRows(const QMenu& menu, QString& rows) {
  for (QAction* action : menu.actions()) {
    if (action->menu()) {
      addShortcutRows(*action->menu(), rows);
      continue;
    }
    QStringList keys;
    for (const QKeySequence& shortcut : action->shortcuts())
      keys << shortcut.toString(QKeySequence::NativeText).toHtmlEscaped();
    if (keys.isEmpty()) continue;
    const QString what = QString(action->text()).remove(QLatin1Char('&')).toHtmlEscaped();
    rows += row(
        keys.join(QStringLiteral(" / ")),
        QStringLiteral("%1 <i>(%2)</i>").arg(what, QString(menu.title()).remove(QLatin1Char('&'))));
  }
}

}  // namespace

QString readingTheChartsText() {
  QString methods;
  for (const BackendInfo& backend : registeredBackends()) {
    methods += QStringLiteral("<li><b>%1</b>: %2</li>")
                   .arg(fromView(backend.name), fromView(backend.description).toHtmlEscaped());
  }
  return QObject::tr(
             "<h3>Restitution is 1: why does my energy change?</h3>"
             "<p><b>Energy</b> shows kinetic, potential (m·g·height) and their total. With "
             "restitution 1 and no drag the total should stay put; the mouse tools and edits "
             "change it on purpose.</p>"
             "<p><b>Energy budget residual</b> = E(t) − E(0) − the work of the mouse tools and "
             "edits + the energy air resistance took. Everything the scene does on purpose is "
             "booked, so what is left is the <i>method's own error</i>: rounding (about 1e-15 "
             "of E) for the exact and elastic methods, more for methods that resolve contacts "
             "iteratively or by moving positions. Tiny and huge values are drawn in a power of "
             "ten named in the axis title; ÷|E₀| shows it relative to the run's total energy "
             "where its budget began (load or restart): the relative energy error of %2.</p>"
             "<p><b>Momentum</b> Σ m·v: conserved by every collision between balls; walls and "
             "gravity change it.</p>"
             "<h3>Compare mode and the chaos baseline</h3>"
             "<p>Several runs step the same scene in lockstep: the same start, step, forces and "
             "edits. <b>Divergence</b> is each run's RMS position difference from run 0. "
             "Bouncing balls are chaotic, so any difference grows: the grey dashed <b>chaos "
             "baseline</b> is run 0 again with every ball moved 1e-9 m. A run whose divergence "
             "follows it differs from run 0 only as chaos allows; one that departs much sooner "
             "differs by its method.</p>"
             "<h3>The methods</h3><ul>%1</ul>"
             "<p>Where each one fails, and why: %3, or <tt>fooball-cli failure-map</tt>. "
             "Scene files: %4.</p>")
      .arg(methods,
           docLink(QStringLiteral("accuracy.md"), QStringLiteral("the-relative-energy-error")),
           docLink(QStringLiteral("accuracy.md")), docLink(QStringLiteral("scene-format.md")));
}

void showReadingTheCharts(QWidget* parent) {
  QMessageBox box(QMessageBox::Information, QObject::tr("Reading the charts"), QString(),
                  QMessageBox::Ok, parent);
  box.setTextFormat(Qt::RichText);
  box.setTextInteractionFlags(Qt::TextBrowserInteraction);
  box.setText(readingTheChartsText());
  box.exec();
}

QString mouseAndKeysText(const QMenuBar& menus) {
  QString shortcuts;
  for (QAction* action : menus.actions()) {
    if (action->menu()) addShortcutRows(*action->menu(), shortcuts);
  }
  return QObject::tr("<h3>Mouse</h3><table>") +
         row(QObject::tr("Left button"),
             QObject::tr("the mouse tool: attract, repel, grab or slingshot. Grab and the "
                         "slingshot take the ball under the cursor when you press, or else the "
                         "nearest one, and draw it ringed while you hold the button; pull back "
                         "and release to shoot it")) +
         row(QObject::tr("Right button"), QObject::tr("place a permanent attractor")) +
         row(QObject::tr("Click while paused"),
             QObject::tr("select a ball and edit it in the sidebar")) +
         row(QObject::tr("Timeline"),
             QObject::tr("in the status bar, while paused: drag to go back to an earlier "
                         "moment; continuing from there drops what came after")) +
         row(QObject::tr("Wheel"),
             QObject::tr("scrolls the sidebar; a slider or field takes it only once clicked")) +
         QObject::tr("</table><h3>Keys</h3><table>") + shortcuts + QStringLiteral("</table>");
}

void showMouseAndKeys(QWidget* parent, const QMenuBar& menus) {
  QMessageBox::information(parent, QObject::tr("Mouse and keys"), mouseAndKeysText(menus));
}

}  // namespace fooball::gui

#include "help_dialogs.h"

#include <QMessageBox>
#include <QObject>

#include "fooball/version.h"
#include "view_text.h"

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

void showMouseAndKeys(QWidget* parent) {
  QMessageBox::information(
      parent, QObject::tr("Mouse and keys"),
      QObject::tr(
          "<table>"
          "<tr><td><b>Left button</b></td><td>the mouse tool: attract, repel, grab or "
          "slingshot (pull back and release)</td></tr>"
          "<tr><td><b>Right button</b></td><td>place a permanent attractor</td></tr>"
          "<tr><td><b>Space</b></td><td>pause / continue</td></tr>"
          "<tr><td><b>.</b></td><td>single step while paused</td></tr>"
          "<tr><td><b>Click while paused</b></td><td>select a ball and edit it in the "
          "sidebar</td></tr>"
          "<tr><td><b>Ctrl+R / Ctrl+Shift+R</b></td><td>restart / reset the scene</td></tr>"
          "<tr><td><b>Ctrl+1 / Ctrl+2</b></td><td>show or hide the settings / charts</td></tr>"
          "<tr><td><b>Ctrl+T, Ctrl+L, Ctrl+Shift+V, Ctrl+M</b></td><td>temperature colouring, "
          "tethers, velocity vectors, centre of mass</td></tr>"
          "<tr><td><b>Ctrl+Shift+B</b></td><td>compare runs side by side</td></tr>"
          "</table>"));
}

}  // namespace fooball::gui

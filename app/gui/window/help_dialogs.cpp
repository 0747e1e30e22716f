#include "window/help_dialogs.h"

#include <QMessageBox>
#include <QObject>

#include "fooball/version.h"
#include "registry.h"
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

void showReadingTheCharts(QWidget* parent) {
  QString methods;
  for (const BackendInfo& backend : registeredBackends()) {
    methods += QStringLiteral("<li><b>%1</b>: %2</li>")
                   .arg(fromView(backend.name), fromView(backend.description).toHtmlEscaped());
  }
  QMessageBox box(QMessageBox::Information, QObject::tr("Reading the charts"), QString(),
                  QMessageBox::Ok, parent);
  box.setTextFormat(Qt::RichText);
  box.setText(
      QObject::tr(
          "<h3>Restitution is 1: why does my energy change?</h3>"
          "<p><b>Energy</b> shows kinetic, potential (m·g·height) and their total. With "
          "restitution 1 and no drag the total should stay put; the mouse tools and edits change "
          "it on purpose.</p>"
          "<p><b>Energy budget residual</b> = E(t) − E(0) − the work of the mouse tools and edits "
          "+ "
          "the energy air resistance took. Everything the scene does on purpose is booked, so "
          "what is left is the <i>method's own error</i>: rounding (about 1e-15 of E) for the "
          "exact "
          "and elastic methods, more for methods that resolve contacts iteratively or by moving "
          "positions. Tiny and huge values are drawn in a power of ten named in the axis title; "
          "÷|E₀| shows it relative to the run's total energy where its budget began (load or "
          "restart): the relative energy error of docs/accuracy.md.</p>"
          "<p><b>Momentum</b> Σ m·v: conserved by every collision between balls; walls and "
          "gravity change it.</p>"
          "<h3>Compare mode and the chaos baseline</h3>"
          "<p>Several runs step the same scene in lockstep: the same start, step, forces and "
          "edits. <b>Divergence</b> is each run's RMS position difference from run 0. Bouncing "
          "balls are chaotic, so any difference grows: the grey dashed <b>chaos baseline</b> is "
          "run 0 again with every ball moved 1e-9 m. A run whose divergence follows it differs "
          "from run 0 only as chaos allows; one that departs much sooner differs by its method.</p>"
          "<h3>The methods</h3><ul>%1</ul>"
          "<p>Where each one fails, and why: docs/accuracy.md, or <tt>fooball-cli failure-map</tt>."
          "</p>")
          .arg(methods));
  box.exec();
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
          "<tr><td><b>,</b></td><td>step back (rewind 0.1 s) while paused</td></tr>"
          "<tr><td><b>Esc</b></td><td>give the keyboard back to the box (after editing a "
          "field)</td></tr>"
          "<tr><td><b>Click while paused</b></td><td>select a ball and edit it in the "
          "sidebar</td></tr>"
          "<tr><td><b>Delete</b></td><td>delete the selected ball</td></tr>"
          "<tr><td><b>Ctrl+Z / Ctrl+Shift+Z</b></td><td>undo / redo the last edit or delete of "
          "a ball</td></tr>"
          "<tr><td><b>Ctrl+R / Ctrl+Shift+R</b></td><td>restart / reset the scene</td></tr>"
          "<tr><td><b>Ctrl+1 / Ctrl+2</b></td><td>show or hide the settings / charts</td></tr>"
          "<tr><td><b>Ctrl+T, Ctrl+L, Ctrl+Shift+V, Ctrl+M</b></td><td>temperature colouring, "
          "tethers, velocity vectors, centre of mass</td></tr>"
          "<tr><td><b>Ctrl+Shift+L</b></td><td>show or hide the preset's “what to look "
          "for” caption</td></tr>"
          "<tr><td><b>Ctrl+Shift+B</b></td><td>compare runs side by side</td></tr>"
          "</table>"));
}

}  // namespace fooball::gui

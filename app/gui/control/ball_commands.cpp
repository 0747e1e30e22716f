#include "control/ball_commands.h"

#include <QUndoCommand>
#include <QUndoStack>
#include <optional>
#include <utility>

#include "fooball/ball_problem.h"
#include "frames/run_feed.h"
#include "run/run_controller.h"
#include "sidebar/ball_inspector.h"
#include "widgets/user_messages.h"

namespace fooball::gui {

namespace {

/// One change of one ball, which can say beforehand why undoing or redoing it would be refused
/// now (QUndoStack moves on whatever undo() does, so the check comes first).
class BallCommand : public QUndoCommand {
 public:
  BallCommand(RunController& runs, std::size_t index, BallStates before, const QString& text)
      : QUndoCommand(text), runs_(runs), index_(index), before_(std::move(before)) {}

  virtual std::optional<BallProblem> undoProblem() const = 0;
  virtual std::optional<BallProblem> redoProblem() const = 0;

  void redo() override {
    // push() calls redo(): the change is made already, by the code that pushed it.
    if (std::exchange(firstRedo_, false)) return;
    applyRedo();
  }

 protected:
  virtual void applyRedo() = 0;
  RunController& runs() const { return runs_; }

  RunController& runs_;
  std::size_t index_;
  BallStates before_;  ///< the ball in every run before the change

 private:
  bool firstRedo_ = true;
};

class EditCommand : public BallCommand {
 public:
  EditCommand(RunController& runs, std::size_t index, BallStates before, BallStates after,
              const QString& text)
      : BallCommand(runs, index, std::move(before), text), after_(std::move(after)) {}

  std::optional<BallProblem> undoProblem() const override {
    return runs().group().findRestoreProblem(index_, before_, BallPlacement::Replace);
  }
  std::optional<BallProblem> redoProblem() const override {
    return runs().group().findRestoreProblem(index_, after_, BallPlacement::Replace);
  }
  void undo() override { restore(before_); }

 private:
  void applyRedo() override { restore(after_); }
  void restore(const BallStates& saved) {
    runs().restoreBall(index_, saved, BallPlacement::Replace);
    runs().setSelected(index_);
  }

  BallStates after_;
};

class DeleteCommand : public BallCommand {
 public:
  using BallCommand::BallCommand;

  std::optional<BallProblem> undoProblem() const override {
    return runs().group().findRestoreProblem(index_, before_, BallPlacement::Insert);
  }
  std::optional<BallProblem> redoProblem() const override { return std::nullopt; }
  void undo() override {
    runs().restoreBall(index_, before_, BallPlacement::Insert);
    runs().setSelected(index_);
  }

 private:
  void applyRedo() override { runs().deleteBall(index_); }
};

/// "move of ball 7": what the edit changed, for the Undo and Redo actions' text.
QString editText(std::size_t index, const BallDef& before, const BallDef& after) {
  int changes = 0;
  QString what;
  const auto note = [&](bool changed, const QString& name) {
    if (!changed) return;
    ++changes;
    what = name;
  };
  note(before.position != after.position, QObject::tr("move"));
  note(before.velocity != after.velocity, QObject::tr("velocity change"));
  note(before.radius != after.radius, QObject::tr("resize"));
  note(before.radius == after.radius && before.mass != after.mass, QObject::tr("mass change"));
  note(before.color != after.color, QObject::tr("colour change"));
  if (changes != 1) what = QObject::tr("edit");
  return QObject::tr("%1 of ball %2").arg(what).arg(index);
}

/// The command Undo (`undo`) or Redo would apply next, or nullptr.
const BallCommand* nextCommand(const QUndoStack& stack, bool undo) {
  const int index = undo ? stack.index() - 1 : stack.index();
  // Every command on the stack is a BallCommand: only this file pushes any.
  return static_cast<const BallCommand*>(stack.command(index));
}

}  // namespace

void BallCommands::undoOrRedo(bool undo) {
  QUndoStack& stack = parts_.undoStack;
  const BallCommand* command = nextCommand(stack, undo);
  if (command == nullptr) return;
  const QString action = undo ? QObject::tr("undo %1") : QObject::tr("redo %1");
  const QString text = action.arg(command->text());
  if (const auto problem = undo ? command->undoProblem() : command->redoProblem()) {
    parts_.messages.showStatus(
        QObject::tr("Cannot %1: %2").arg(text, QString::fromStdString(plainWords(*problem))));
    return;
  }
  if (undo) {
    stack.undo();
  } else {
    stack.redo();
  }
  parts_.feed.markChange(text);
  parts_.feed.showSelectedBall();
}

void BallCommands::editBall(std::size_t index, const BallDef& edited) {
  const BallDef before = parts_.runs.group().ball(index);
  BallStates saved = parts_.runs.group().ballStates(index);
  try {
    const BallDef after = parts_.runs.editBall(index, edited);
    parts_.undoStack.push(new EditCommand(parts_.runs, index, std::move(saved),
                                          parts_.runs.group().ballStates(index),
                                          editText(index, before, after)));
    parts_.feed.markChange(QObject::tr("ball #%1 edited").arg(index));
  } catch (const SceneError& error) {
    const auto* refused = dynamic_cast<const BallError*>(&error);
    const QString message =
        QString::fromStdString(refused ? plainWords(refused->problem()) : error.what());
    parts_.inspector.showBall(index, parts_.runs.group().ball(index), true);
    parts_.inspector.showError(message);
    parts_.messages.showStatus(message);
  }
  parts_.feed.showSelectedBall();
}

void BallCommands::deleteBall(std::size_t index) {
  BallStates saved = parts_.runs.group().ballStates(index);
  parts_.runs.deleteBall(index);
  parts_.undoStack.push(new DeleteCommand(parts_.runs, index, std::move(saved),
                                          QObject::tr("delete of ball %1").arg(index)));
  parts_.feed.markChange(QObject::tr("ball #%1 deleted").arg(index));
}

}  // namespace fooball::gui

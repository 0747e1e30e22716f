#pragma once

#include <QLayout>
#include <QList>

namespace fooball::gui {

/// Lays its items out in rows, left to right, starting a new row where the next item would pass
/// the right edge: a row of controls that wraps in a narrow panel instead of hiding what does not
/// fit. Its height follows its width (heightForWidth), so the parent's layout gives it the rows
/// it needs.
class FlowLayout : public QLayout {
 public:
  /// `horizontalSpacing` and `verticalSpacing` in px, between items in a row and between rows.
  FlowLayout(QWidget* parent, int horizontalSpacing, int verticalSpacing);
  ~FlowLayout() override;

  void addItem(QLayoutItem* item) override;
  int count() const override;
  QLayoutItem* itemAt(int index) const override;
  QLayoutItem* takeAt(int index) override;
  Qt::Orientations expandingDirections() const override;
  bool hasHeightForWidth() const override;
  int heightForWidth(int width) const override;
  /// As wide as the widest item: every item fits a row of its own.
  QSize minimumSize() const override;
  /// Every item in one row.
  QSize sizeHint() const override;
  void setGeometry(const QRect& rect) override;

 private:
  /// Places the items in `rect` (or only measures, when `place` is false); returns the height used.
  int arrange(const QRect& rect, bool place) const;

  QList<QLayoutItem*> items_;
  int horizontalSpacing_;
  int verticalSpacing_;
};

}  // namespace fooball::gui

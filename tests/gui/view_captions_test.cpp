// Legends and hints around the box: none covers any of a box (the stated fraction is 0: they
// sit in rows above the boxes, or on the line above a tile), and none overlaps another, at every
// window size, with every caption there is at once (eight runs, paused, temperature colours).

#include <QAction>

#include "gui_fixture.h"
#include "window/window_actions.h"

namespace fooball::gui::testing {
namespace {

using Caption = SimulationView::Caption;

class ViewCaptions : public GuiTest {
 protected:
  void expectApart(const std::string& where) const {
    const std::vector<Caption> captions = view()->captions();
    const int tiles = view()->compareLayout() == CompareLayout::SideBySide ? runs().runCount() : 1;
    for (std::size_t i = 0; i < captions.size(); ++i) {
      const Caption& caption = captions[i];
      EXPECT_FALSE(caption.rect.isEmpty()) << where << ": " << caption.text.toStdString();
      EXPECT_TRUE(view()->rect().contains(caption.rect))
          << where << ": " << caption.text.toStdString() << " leaves the view";
      for (int run = 0; run < tiles; ++run) {
        // The wall is drawn one pixel outside the box: a caption may not touch it either.
        const QRect box = view()->transformForRun(run).boxRect().adjusted(-1, -1, 1, 1);
        EXPECT_FALSE(caption.rect.intersects(box))
            << where << ": " << caption.text.toStdString() << " covers box " << run;
      }
      for (std::size_t j = i + 1; j < captions.size(); ++j) {
        EXPECT_FALSE(caption.rect.intersects(captions[j].rect))
            << where << ": " << caption.text.toStdString() << " overlaps "
            << captions[j].text.toStdString();
      }
    }
  }

  std::size_t count(Caption::Kind kind) const {
    const auto captions = view()->captions();
    return std::size_t(std::count_if(captions.begin(), captions.end(),
                                     [kind](const Caption& c) { return c.kind == kind; }));
  }
};

TEST_F(ViewCaptions, NoneCoversTheBoxOrAnotherAtAnySize) {
  const std::vector<std::string> seven{"exact",
                                       "box2d",
                                       "chipmunk",
                                       "xpbd",
                                       "elastic:substeps=1",
                                       "box2d:substeps=1",
                                       "exact:max_events_per_ball=50"};
  for (const std::vector<std::string>& compare :
       {std::vector<std::string>{}, std::vector<std::string>{"exact", "box2d"}, seven}) {
    open(stillBalls(), "elastic", compare);
    window->actions().temperature()->setChecked(true);
    runs().setPaused(true);
    for (const CompareLayout layout : {CompareLayout::Overlay, CompareLayout::SideBySide}) {
      view()->setCompareLayout(layout);
      for (const QSize size :
           {QSize(1000, 650), QSize(1440, 900), QSize(2560, 1440), QSize(3840, 2160)}) {
        window->resize(size);
        for (int i = 0; i < 3; ++i)
          QCoreApplication::processEvents();
        const std::string where = std::to_string(compare.size() + 1) + " runs, " +
                                  (layout == CompareLayout::Overlay ? "overlay" : "side by side") +
                                  " at " + std::to_string(size.width());
        EXPECT_EQ(count(Caption::Kind::Paused), 1u) << where;
        EXPECT_EQ(count(Caption::Kind::Temperature), 1u) << where;
        if (compare.empty()) {
          EXPECT_EQ(count(Caption::Kind::RunEntry) + count(Caption::Kind::TileLabel), 0u) << where;
        } else if (layout == CompareLayout::Overlay) {
          EXPECT_EQ(count(Caption::Kind::RunEntry), compare.size() + 1) << where;
        } else {
          EXPECT_EQ(count(Caption::Kind::TileLabel), compare.size() + 1) << where;
        }
        expectApart(where);
      }
    }
  }
}

TEST_F(ViewCaptions, PausingDoesNotMoveTheBox) {
  open(stillBalls(), "elastic", {"exact"});
  const QRect running = view()->transformForRun(0).boxRect();
  runs().setPaused(true);
  EXPECT_EQ(view()->transformForRun(0).boxRect(), running);
  EXPECT_EQ(count(Caption::Kind::Paused), 1u);
  runs().setPaused(false);
  EXPECT_EQ(count(Caption::Kind::Paused), 0u);
}

}  // namespace
}  // namespace fooball::gui::testing

// The 3D view's scene layers without a widget (issue 31): a MarkerScene draws a document's frame
// into a plain vtkRenderer (no window, no QWidget), so the studio's view and a review video add the
// same layers: markers (drawn, hidden, missing, coloured by selection and layout highlight), trails
// broken at gaps, links, labels, the head-stabilized positions, and the actors gone with the scene.
#include "document/take_document.h"
#include "views/layout_highlight_colors.h"
#include "views/link_layer.h"
#include "views/marker_layer.h"
#include "views/marker_scene.h"
#include "views/sample_colors.h"
#include "views/selection_palette.h"
#include "views/trail_layer.h"

#include <vtkActor.h>
#include <vtkBillboardTextActor3D.h>
#include <vtkMapper.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkPropCollection.h>
#include <vtkRenderer.h>

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace mocap {
namespace {

constexpr Eigen::Index kSceneFrames = 10;
constexpr Eigen::Index kSceneGapFrame = 5;

/// Four markers at a square's corners and one above its middle, the whole head moving 10 units along
/// x a frame; marker 2 is missing at kSceneGapFrame.
Take movingHeadTake()
{
  Take take({"a", "b", "c", "d", "e"}, kSceneFrames, 100.0);
  const std::vector<Eigen::Vector3d> corners = {Eigen::Vector3d(0.0, 0.0, 0.0), Eigen::Vector3d(100.0, 0.0, 0.0),
                                                Eigen::Vector3d(100.0, 100.0, 0.0), Eigen::Vector3d(0.0, 100.0, 0.0),
                                                Eigen::Vector3d(50.0, 50.0, 40.0)};
  for (Eigen::Index f = 0; f < kSceneFrames; ++f)
    for (Eigen::Index m = 0; m < take.markerCount(); ++m) {
      take.setPosition(f, m, corners[static_cast<std::size_t>(m)] + Eigen::Vector3d(10.0 * static_cast<double>(f), 0.0, 0.0));
      take.valid()(f, m) = !(m == 2 && f == kSceneGapFrame);
    }
  return take;
}

/// The text labels `renderer` shows.
std::vector<std::string> shownLabels(vtkRenderer& renderer)
{
  std::vector<std::string> texts;
  vtkPropCollection* props = renderer.GetViewProps();
  props->InitTraversal();
  while (vtkProp* prop = props->GetNextProp())
    if (auto* label = vtkBillboardTextActor3D::SafeDownCast(prop); label && label->GetVisibility())
      texts.emplace_back(label->GetInput());
  return texts;
}

vtkPolyData* drawnLines(vtkActor* actor)
{
  return vtkPolyData::SafeDownCast(actor->GetMapper()->GetInput());
}

class MarkerSceneLayers : public ::testing::Test
{
protected:
  void SetUp() override
  {
    document.setTake(movingHeadTake());
    document.setCurrentFrame(kSceneGapFrame);
    scene.sizeToTake();
  }

  vtkNew<vtkRenderer> renderer;
  ui::TakeDocument document;
  ui::MarkerScene scene{renderer, document};
};

TEST_F(MarkerSceneLayers, DrawTheFramesMarkersTrailsAndLabelsIntoARendererWithNoWidget)
{
  document.setSelection({0, 2});
  document.setHidden({3}, true);
  scene.update();
  // Marker 2 is missing in this frame and marker 3 hidden: neither is drawn, nor labelled.
  const ui::MarkerLayer& markers = scene.markerLayer();
  EXPECT_EQ(markers.drawnMarkers(), (std::vector<Eigen::Index>{0, 1, 4}));
  EXPECT_EQ(markers.colorOf(0), ui::selectionPaletteColor(0));
  EXPECT_EQ(markers.colorOf(1), ui::stateColor(document.take().state(kSceneGapFrame, 1)));
  EXPECT_FALSE(markers.colorOf(2).has_value());
  EXPECT_FALSE(markers.colorOf(3).has_value());
  EXPECT_TRUE(markers.point(0).isApprox(Eigen::Vector3d(50.0, 0.0, 0.0)));
  EXPECT_EQ(shownLabels(*renderer), (std::vector<std::string>{"a"}));
  // Marker 0's trail is whole over the ten frames; marker 2's is broken at its gap.
  vtkPolyData* trails = drawnLines(scene.trailLayer().actor());
  ASSERT_NE(trails, nullptr);
  EXPECT_EQ(trails->GetNumberOfLines(), 3);
  EXPECT_EQ(trails->GetNumberOfPoints(), kSceneFrames + kSceneFrames - 1);
  scene.setTrailFrames(0);
  scene.update();
  EXPECT_EQ(drawnLines(scene.trailLayer().actor())->GetNumberOfLines(), 0);
}

TEST_F(MarkerSceneLayers, ShowAPlannedLayoutInItsColoursAndLabelTheKeptMarkers)
{
  scene.setLayoutHighlight({true, false, false, true, false}, {false, true, false, false, false});
  scene.update();
  const ui::MarkerLayer& markers = scene.markerLayer();
  EXPECT_EQ(markers.colorOf(0), ui::layoutKeptColor());
  EXPECT_EQ(markers.colorOf(1), QColor(40, 110, 255));  // a reference marker the plan leaves out
  EXPECT_EQ(markers.colorOf(4), QColor(85, 85, 92));    // dropped
  EXPECT_EQ(shownLabels(*renderer), (std::vector<std::string>{"a", "d"}));
  // A highlight of another take's marker count is none.
  scene.setLayoutHighlight({true, false}, {});
  scene.update();
  EXPECT_TRUE(scene.layoutHighlight().empty());
  EXPECT_EQ(markers.colorOf(0), ui::stateColor(document.take().state(kSceneGapFrame, 0)));
  EXPECT_TRUE(shownLabels(*renderer).empty());
}

TEST_F(MarkerSceneLayers, LinkNeighboursWhereBothEndsAreDrawn)
{
  scene.update();
  EXPECT_TRUE(scene.links().empty());  // found when first shown
  scene.setLinksVisible(true);
  scene.update();
  const std::vector<MarkerLink>& links = scene.links();
  ASSERT_FALSE(links.empty());
  vtkIdType drawable = 0;
  for (const auto& [a, b] : links)
    drawable += a != 2 && b != 2 ? 1 : 0;
  EXPECT_LT(drawable, static_cast<vtkIdType>(links.size()));  // some link ends at the missing marker
  EXPECT_TRUE(scene.linkLayer().actor()->GetVisibility());
  EXPECT_EQ(drawnLines(scene.linkLayer().actor())->GetNumberOfLines(), drawable);
  scene.setLinksVisible(false);
  EXPECT_FALSE(scene.linkLayer().actor()->GetVisibility());
}

TEST_F(MarkerSceneLayers, DrawTheMarkersStillInTheHeadStabilizedFrame)
{
  EXPECT_FALSE(scene.positions().setHeadReference({0, 1}).isEmpty()) << "two markers carry no head pose";
  EXPECT_FALSE(scene.positions().stabilized());
  ASSERT_TRUE(scene.positions().setHeadReference({0, 1, 3, 4}).isEmpty());
  EXPECT_TRUE(scene.positions().stabilized());
  // The whole head moves: held still, every marker stays where it is in the reference frame.
  for (Eigen::Index f = 1; f < kSceneFrames; ++f)
    EXPECT_TRUE(scene.positions().at(f, 4).isApprox(scene.positions().at(0, 4), 1e-9)) << "frame " << f;
  scene.update();
  EXPECT_TRUE(scene.markerLayer().point(0).isApprox(scene.positions().at(0, 0).cast<float>().cast<double>(), 1e-6));
  scene.forgetMarkerIndices();
  EXPECT_FALSE(scene.positions().stabilized());
}

TEST(MarkerSceneActors, AreTakenOutOfTheRendererWithTheScene)
{
  vtkNew<vtkRenderer> renderer;
  ui::TakeDocument document;
  document.setTake(movingHeadTake());
  {
    ui::MarkerScene scene(renderer, document);
    document.setSelection({0, 1});
    scene.update();
    EXPECT_EQ(renderer->GetViewProps()->GetNumberOfItems(), 3 + 2);  // markers, trails, links, two labels
  }
  EXPECT_EQ(renderer->GetViewProps()->GetNumberOfItems(), 0);
}

} // namespace
} // namespace mocap

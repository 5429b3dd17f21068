// One inspection view through VTK's rendering: a coloured data set, its colour bar, context
// geometry and overlays. Debian's VTK 9.1 renders only through X: the caller hands the display.
#include "view_render.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellData.h>
#include <vtkLookupTable.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkTubeFilter.h>

#include <cmath>

#include "vtk_io.h"

namespace tissue::inspect {
namespace {

using Rgb = std::array<double, 3>;
/// Viridis (perceptually uniform, colour-vision-deficiency safe) and Moreland's cool-warm
/// diverging map, as control points interpolated linearly.
constexpr std::array<Rgb, 5> kViridis{{{0.267, 0.005, 0.329},
                                       {0.229, 0.322, 0.546},
                                       {0.128, 0.567, 0.551},
                                       {0.369, 0.789, 0.383},
                                       {0.993, 0.906, 0.144}}};
constexpr std::array<Rgb, 3> kCoolWarm{{{0.230, 0.299, 0.754}, {0.865, 0.865, 0.865}, {0.706, 0.016, 0.150}}};
constexpr std::array<Rgb, 2> kTwoTone{{{0.95, 0.70, 0.15}, {0.86, 0.86, 0.86}}};

template <std::size_t N>
vtkSmartPointer<vtkLookupTable> lookupTable(const std::array<Rgb, N>& points, std::array<double, 2> range) {
  auto table = vtkSmartPointer<vtkLookupTable>::New();
  constexpr int kEntries = 256;
  table->SetNumberOfTableValues(kEntries);
  for (int e = 0; e < kEntries; ++e) {
    const double t = double(e) / (kEntries - 1) * double(N - 1);
    const std::size_t k = std::min(std::size_t(t), N - 2);
    const double f = t - double(k);
    table->SetTableValue(e, points[k][0] + f * (points[k + 1][0] - points[k][0]),
                         points[k][1] + f * (points[k + 1][1] - points[k][1]),
                         points[k][2] + f * (points[k + 1][2] - points[k][2]), 1.0);
  }
  table->SetNanColor(0.35, 0.35, 0.35, 1.0);  // no value (e.g. a hidden vertex of the truth error)
  // A flat field still gets a bar with a readable range.
  if (!(range[1] > range[0])) range = {range[0] - 0.5, range[0] + 0.5};
  table->SetTableRange(range[0], range[1]);
  table->Build();
  return table;
}

/// Builds the renderer of `scene` into `window`.
void buildScene(const ViewScene& scene, vtkRenderWindow* window, const ViewImage& size) {
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(1.0, 1.0, 1.0);
  window->AddRenderer(renderer);
  window->SetSize(size.widthPx, size.heightPx);

  // The coloured data (tubes for lines when asked).
  auto table = scene.palette == ViewScene::Palette::CoolWarm  ? lookupTable(kCoolWarm, scene.range)
               : scene.palette == ViewScene::Palette::TwoTone ? lookupTable(kTwoTone, scene.range)
                                                              : lookupTable(kViridis, scene.range);
  vtkNew<vtkPolyDataMapper> mapper;
  if (scene.tubes) {
    vtkNew<vtkTubeFilter> tubes;
    tubes->SetInputData(scene.data);
    tubes->SetRadius(scene.tubeRadius);
    tubes->SetNumberOfSides(6);
    mapper->SetInputConnection(tubes->GetOutputPort());
  } else {
    mapper->SetInputData(scene.data);
  }
  mapper->SetLookupTable(table);
  mapper->SetUseLookupTableScalarRange(true);
  mapper->SetScalarModeToUsePointFieldData();
  if (scene.cellArray) mapper->SetScalarModeToUseCellFieldData();
  mapper->SelectColorArray(scene.array.c_str());
  mapper->ScalarVisibilityOn();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetLineWidth(2.0f);
  renderer->AddActor(actor);

  // Context (grey, translucent) and overlays (fixed colours).
  if (scene.context) {
    vtkNew<vtkPolyDataMapper> contextMapper;
    contextMapper->SetInputData(scene.context);
    contextMapper->ScalarVisibilityOff();
    vtkNew<vtkActor> contextActor;
    contextActor->SetMapper(contextMapper);
    contextActor->GetProperty()->SetColor(0.75, 0.75, 0.75);
    contextActor->GetProperty()->SetOpacity(0.35);
    renderer->AddActor(contextActor);
  }
  std::string legend;
  for (const ViewOverlay& overlay : scene.overlays) {
    vtkNew<vtkPolyDataMapper> overlayMapper;
    overlayMapper->SetInputData(overlay.geometry);
    overlayMapper->ScalarVisibilityOff();
    vtkNew<vtkActor> overlayActor;
    overlayActor->SetMapper(overlayMapper);
    overlayActor->GetProperty()->SetColor(overlay.rgb[0], overlay.rgb[1], overlay.rgb[2]);
    overlayActor->GetProperty()->SetLineWidth(overlay.lineWidth);
    overlayActor->GetProperty()->SetPointSize(overlay.pointSize);
    overlayActor->GetProperty()->SetOpacity(overlay.opacity);
    renderer->AddActor(overlayActor);
    if (!overlay.legend.empty()) legend += (legend.empty() ? "" : "\n") + overlay.legend;
  }

  // The colour bar on the right, with its title (and unit), and the view's title on top.
  vtkNew<vtkScalarBarActor> bar;
  bar->SetLookupTable(table);
  bar->SetTitle(scene.barTitle.c_str());
  bar->SetNumberOfLabels(5);
  bar->SetLabelFormat("%-#6.3g");
  bar->SetPosition(0.84, 0.08);
  bar->SetWidth(0.14);
  bar->SetHeight(0.8);
  bar->SetBarRatio(0.35);
  bar->UnconstrainedFontSizeOn();
  for (vtkTextProperty* text : {bar->GetTitleTextProperty(), bar->GetLabelTextProperty()}) {
    text->SetColor(0.0, 0.0, 0.0);
    text->SetFontSize(text == bar->GetTitleTextProperty() ? 15 : 14);
    text->ShadowOff();
    text->BoldOff();
    text->ItalicOff();
  }
  renderer->AddActor2D(bar);
  vtkNew<vtkTextActor> title;
  title->SetInput(scene.title.c_str());
  title->GetTextProperty()->SetFontSize(20);
  title->GetTextProperty()->SetColor(0.0, 0.0, 0.0);
  title->SetDisplayPosition(12, size.heightPx - 32);
  renderer->AddActor2D(title);
  if (!legend.empty()) {
    vtkNew<vtkTextActor> legendText;
    legendText->SetInput(legend.c_str());
    legendText->GetTextProperty()->SetFontSize(15);
    legendText->GetTextProperty()->SetColor(0.0, 0.0, 0.0);
    legendText->SetDisplayPosition(12, 12);
    renderer->AddActor2D(legendText);
  }

  // Camera: the data from the front, above and to the side; the bar's margin left free.
  renderer->SetViewport(0.0, 0.0, 1.0, 1.0);
  renderer->ResetCamera();
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetViewUp(0.0, 0.0, 1.0);
  double focal[3];
  camera->GetFocalPoint(focal);
  const double distance = camera->GetDistance();
  camera->SetPosition(focal[0] + 0.35 * distance, focal[1] - 0.75 * distance, focal[2] + 0.55 * distance);
  renderer->ResetCamera();
  camera->Zoom(1.15);
  camera->SetWindowCenter(0.12, 0.0);  // shift the data left of the colour bar
}

}  // namespace

Result<std::vector<std::uint8_t>> renderViewPng(const ViewScene& scene, const ViewImage& size,
                                                void* displayId) {
  if (!scene.data) return Error{"inspection view '" + scene.title + "': no data to draw"};
  vtkNew<vtkRenderWindow> window;
  window->SetDisplayId(displayId);
  window->SetOffScreenRendering(1);
  buildScene(scene, window, size);
  auto png = renderToPng(window);
  window->Finalize();
  if (png.empty())
    return Error{"inspection view '" + scene.title +
                 "': VTK produced no image; check the X display (Xvfb) works"};
  return png;
}

Result<void> showViewWindow(const ViewScene& scene, const ViewImage& size, void* displayId) {
  if (!scene.data) return Error{"inspection view '" + scene.title + "': no data to draw"};
  vtkNew<vtkRenderWindow> window;
  window->SetDisplayId(displayId);
  window->SetWindowName(scene.title.c_str());
  buildScene(scene, window, size);
  vtkNew<vtkRenderWindowInteractor> interactor;
  interactor->SetRenderWindow(window);
  window->Render();
  interactor->Start();  // returns when the user closes the window
  window->Finalize();
  return {};
}

}  // namespace tissue::inspect

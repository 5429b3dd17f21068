// The views' names (built with and without VTK).
#include "tissue/inspect/inspection_views.h"

namespace tissue::inspect {

std::string viewName(InspectionView view) {
  switch (view) {
    case InspectionView::SpringStrain:
      return "spring_strain";
    case InspectionView::VertexStretch:
      return "vertex_stretch";
    case InspectionView::ContactForce:
      return "contact_force";
    case InspectionView::PlaneFit:
      return "plane_fit";
    case InspectionView::TangentFrames:
      return "tangent_frames";
    case InspectionView::TextureStretch:
      return "texture_stretch";
  }
  return "view";
}

}  // namespace tissue::inspect

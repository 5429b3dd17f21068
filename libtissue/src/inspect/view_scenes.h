#pragma once
/// \file
/// Private: the VTK scene of each inspection view, built from a snapshot's plain arrays. The
/// scene's data set (with every array of the view) is also what the view's .vtp holds.

#include "tissue/core/result.h"
#include "tissue/inspect/inspection_views.h"
#include "view_render.h"

namespace tissue::inspect {

/// The scene of `view`. Fails when the snapshot's arrays do not match its meshes.
Result<ViewScene> buildViewScene(const OrganSnapshot& frame, InspectionView view,
                                 const ViewSettings& settings);
/// The scene of the truth-error hook. Fails when the map has not one value per render vertex.
Result<ViewScene> buildTruthErrorScene(const OrganSnapshot& frame, const TruthErrorMap& error);

}  // namespace tissue::inspect

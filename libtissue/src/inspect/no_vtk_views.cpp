// The inspection views and the ParaView series built without VTK (TISSUE_WITH_VTK=OFF): the
// snapshots still compute (organ_snapshot.cpp); every image and file is one Error saying so.
#include "tissue/inspect/inspection_views.h"
#include "tissue/inspect/pvd_series.h"

namespace tissue::inspect {
namespace {

Error withoutVtk(const std::string& what) {
  return Error{what + ": built without VTK (TISSUE_WITH_VTK=OFF); rebuild with -DTISSUE_WITH_VTK=ON"};
}

}  // namespace

Result<WrittenView> writeInspectionView(const OrganSnapshot&, InspectionView view,
                                        const std::filesystem::path& dir, const ViewSettings&) {
  return withoutVtk((dir / viewName(view)).string() + ": cannot write an inspection view");
}

Result<WrittenView> writeTruthErrorView(const OrganSnapshot&, const TruthErrorMap&,
                                        const std::filesystem::path& dir, const ViewSettings&) {
  return withoutVtk((dir / "truth_error").string() + ": cannot write an inspection view");
}

Result<std::vector<WrittenView>> writeInspectionViews(const OrganSnapshot&, const std::filesystem::path& dir,
                                                      const ViewSettings&, const TruthErrorMap*) {
  return withoutVtk(dir.string() + ": cannot write the inspection views");
}

Result<void> showInspectionWindow(const OrganSnapshot&, InspectionView view, const ViewSettings&) {
  return withoutVtk("cannot open the " + viewName(view) + " inspection window");
}

bool hasDisplay() {
  return false;
}

PvdSeries::PvdSeries(std::filesystem::path dir, std::string name)
    : m_dir(std::move(dir)), m_name(std::move(name)), m_pvd(m_dir / (m_name + ".pvd")) {}

Result<PvdSeries> PvdSeries::create(const std::filesystem::path& dir, const std::string& name) {
  return withoutVtk((dir / (name + ".pvd")).string() + ": cannot write a ParaView series");
}

Result<PvdFrameCost> PvdSeries::addFrame(const OrganSnapshot&) {
  return withoutVtk(m_pvd.string() + ": cannot write a ParaView series");
}

std::vector<std::filesystem::path> PvdSeries::framePaths() const {
  return {};
}

Result<std::filesystem::path> writeOrganFrame(const OrganSnapshot&, const std::filesystem::path& path) {
  return withoutVtk(path.string() + ": cannot write a ParaView frame");
}

}  // namespace tissue::inspect

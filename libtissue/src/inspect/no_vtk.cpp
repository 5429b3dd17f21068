// The inspect module built without VTK (TISSUE_WITH_VTK=OFF): the exports and charts are not
// compiled in; each call is one Error that names the file it was asked to write, so apps and
// hosts link either way and say so at run time.
#include <string>

#include "tissue/inspect/chart.h"
#include "tissue/inspect/vtk_export.h"

namespace tissue::inspect {
namespace {

Error builtWithoutVtk(const std::filesystem::path& path, const char* what) {
  return Error{path.string() + ": cannot write " + what +
               ": built without VTK (TISSUE_WITH_VTK=OFF); rebuild with -DTISSUE_WITH_VTK=ON"};
}

}  // namespace

bool builtWithVtk() {
  return false;
}

Result<void> writeVtp(const std::filesystem::path& path, std::span<const Float3>, std::span<const Triangle>,
                      const std::vector<VertexField>&) {
  return builtWithoutVtk(path, "a .vtp export");
}

Result<void> writeLineChart(const std::filesystem::path& png, const ChartSettings&,
                            std::span<const ChartSeries>) {
  return builtWithoutVtk(png, "a chart");
}

}  // namespace tissue::inspect

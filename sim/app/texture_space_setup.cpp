// tissue-sim's texture-space set-up: the skin table from the shared folder (texture_space_setup.h).
#include "texture_space_setup.h"

#include <filesystem>

#include "output.h"

namespace tissue::sim_app {

Result<std::vector<render::ProfileGaussian>> skinGaussians(int count) {
  const auto path = sharedDir() / "reference" / "deon_skin_gaussians.tsv";
  if (!std::filesystem::is_regular_file(path))
    return Error{"cannot read " + path.string() + "; set TISSUE_SHARED_DIR to the shared folder"};
  if (count != 2 && count != 4 && count != 6) return Error{"--gaussians must be 2, 4 or 6"};
  return studies::skinGaussians(path, count);
}

}  // namespace tissue::sim_app

#include "mpm/io/view_script.hpp"

#include <fmt/format.h>

#include <fstream>
#include <stdexcept>

#include "mpm/io/atomic_file.hpp"

namespace mpm::io {

std::string view_script(const ViewScript& v) {
  return fmt::format(
      R"PY(# ParaView view of this run, written by mpm. Run it with `pvpython view.py` (an interactive window;
# `pvpython view.py --screenshot FILE.png` saves the last frame instead), or in ParaView with
# View > Python Shell > Run Script. Paths are relative to this file, so the directory can be moved.
import os
import sys

from paraview.simple import *

here = os.path.dirname(os.path.abspath(__file__))
particles = PVDReader(registrationName="{pvd}", FileName=os.path.join(here, "{pvd}"))
view = GetActiveViewOrCreate("RenderView")
display = Show(particles, view)
# Each particle as a disc of the particle radius (half the particle spacing, m).
display.SetRepresentationType("Point Gaussian")
display.GaussianRadius = {radius:.9g}
display.ShaderPreset = "Plain circle"
ColorBy(display, ("POINTS", "{field}"{magnitude}))
display.RescaleTransferFunctionToDataRange(True, False)
display.SetScalarBarVisibility(view, True)
GetAnimationScene().UpdateAnimationUsingDataTimeSteps()
{two_d}view.ResetCamera()
Render(view)

if __name__ == "__main__" and os.path.basename(sys.argv[0] if sys.argv else "") == "view.py":
    if "--screenshot" in sys.argv[1:-1]:
        GetAnimationScene().AnimationTime = GetTimeKeeper().TimestepValues[-1] if GetTimeKeeper().TimestepValues else 0
        SaveScreenshot(sys.argv[sys.argv.index("--screenshot") + 1], view, ImageResolution=[1200, 900])
    else:
        Interact(view)
)PY",
      fmt::arg("pvd", v.particles_pvd), fmt::arg("radius", v.particle_radius), fmt::arg("field", v.colour_by),
      fmt::arg("magnitude", v.colour_components > 1 ? ", \"Magnitude\"" : ""),
      fmt::arg("two_d", v.dimension < 3 ? "view.InteractionMode = \"2D\"\nview.CameraPosition = [0, 0, 1]\n"
                                          "view.CameraFocalPoint = [0, 0, 0]\nview.CameraViewUp = [0, 1, 0]\n"
                                        : ""));
}

void write_view_script(const std::filesystem::path& path, const ViewScript& view) {
  const std::string text = view_script(view);
  write_atomically(path, [&](const std::filesystem::path& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    out << text;
    out.close();
    if (!out) throw std::runtime_error("cannot write '" + path.string() + "'");
  });
}

}  // namespace mpm::io

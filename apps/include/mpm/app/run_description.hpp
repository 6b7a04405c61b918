#pragma once
/// \file run_description.hpp
/// What a run tells about itself in its output directory: the field data of every output file (the scene
/// as read, the changes made to it by the command line, the program version and commit, the thread and rank
/// counts; the writer adds TIME and step) and the ParaView script view.py.

#include <string>
#include <vector>

#include "mpm/io/view_script.hpp"
#include "mpm/io/vtk_writer.hpp"
#include "mpm/scene/scene.hpp"

namespace mpm::app {

/// Field data: `scene` (the YAML text), `scene_file`, `overrides` (one line per change the command line or
/// `mpm verify` made, e.g. "solver.end_time: 0.01"; empty when none), `program` ("mpm 0.1.0"), `commit`;
/// numbers `threads` (the largest parallelism of the run) and `ranks` (1).
io::FieldData run_field_data(const SceneDescription& scene, const std::vector<std::string>& overrides);

/// view.py for the scene's output: colours by von_mises_stress if written, else by the first field written;
/// Point Gaussian radius = half the smallest particle spacing of the bodies.
io::ViewScript view_script_for(const SceneDescription& scene);

}  // namespace mpm::app

// The extension module mpm._mpm: Scene, the dimension-erased simulation behind mpm.Simulation, NumPy views of
// its fields, and the translation of the engine's exceptions into mpm.SceneError and mpm.StabilityError
// (classes of mpm/_errors.py). The Python package (python/mpm/) builds the user-facing API on these.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "mpm/app/modules.hpp"
#include "mpm/core/stability_error.hpp"
#include "mpm/output/output_fields.hpp"
#include "mpm/scene/scene_error.hpp"
#include "scene_binding.hpp"
#include "simulation_handle.hpp"

namespace py = pybind11;

namespace mpm::python {
namespace {

/// An array over `a` that keeps `owner` (the simulation) alive; read-only unless `a.writable`.
py::array array_over(const FieldArray& a, py::handle owner) {
  py::dtype dtype = a.storage.layout.scalar == 'f'   ? py::dtype::of<double>()
                    : a.storage.layout.scalar == 'i' ? py::dtype::of<std::int32_t>()
                                                     : py::dtype::of<std::uint32_t>();
  std::vector<py::ssize_t> shape(a.shape.begin(), a.shape.end()), strides(a.strides.begin(), a.strides.end());
  py::array array(dtype, shape, strides, a.storage.data, owner);
  if (!a.writable) array.attr("flags").attr("writeable") = false;
  return array;
}

void translate_exceptions() {
  // pybind11 takes a function pointer of this exact signature
  py::register_exception_translator([](std::exception_ptr p) {  // NOLINT(performance-unnecessary-value-param)
    try {
      if (p) std::rethrow_exception(p);
    } catch (const SceneError& e) {
      const py::object cls = py::module_::import("mpm._errors").attr("SceneError");
      const bool located = !e.where.file.empty();
      // A dict scene has no file: "key: message", as the program's message without its location.
      const std::string note = app::missing_module_note(e, app::missing_modules());  // as the program's message
      const std::string text =
          (located ? std::string(e.what()) : (e.key.empty() ? e.message : e.key + ": " + e.message)) + note;
      const py::object error =
          cls(text, located ? py::object(py::str(e.where.file)) : py::none(),
              e.where.line > 0 ? py::object(py::int_(e.where.line)) : py::none(),
              e.where.line > 0 ? py::object(py::int_(e.where.column > 0 ? e.where.column : 1)) : py::none(), e.key,
              e.message + note);
      PyErr_SetObject(cls.ptr(), error.ptr());
    } catch (const StabilityError& e) {
      const py::object cls = py::module_::import("mpm._errors").attr("StabilityError");
      const auto& r = e.report();
      const py::object error = cls(e.what(), r.step, r.time, r.body, r.particle, r.field, r.detail,
                                   r.face.empty() ? py::object(py::none()) : py::object(py::str(r.face)));
      PyErr_SetObject(cls.ptr(), error.ptr());
    }
  });
}

std::unique_ptr<SimulationHandle> build(const Scene& scene, int threads, const std::string& output_directory) {
  try {
    py::gil_scoped_release release;  // building fills the bodies with particles, in parallel
    return make_simulation(scene.description, threads, output_directory);
  } catch (const SceneError&) {
    rethrow_for(scene);
  }
}

py::dict energy_dict(const EnergyBalance& e) {
  py::dict d;
  d["kinetic"] = e.kinetic;
  d["strain"] = e.strain;
  d["gravity"] = e.gravity;
  d["plastic_work"] = e.plastic_work;
  d["thermal"] = e.thermal;
  d["total"] = e.total();
  d["momentum"] = std::vector<double>{e.momentum[0], e.momentum[1], e.momentum[2]};
  d["mass"] = e.mass;
  return d;
}

/// A poll function for the stepping calls: with the interpreter lock, raises KeyboardInterrupt on Ctrl-C (the
/// signal handler runs only when Python runs), then calls `poll` unless it is None. `poll` must outlive it.
std::function<void()> python_poll(const py::object& poll) {
  return [&poll] {
    py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    if (!poll.is_none()) poll();
  };
}

void bind_simulation(py::module_& m) {
  using H = SimulationHandle;
  py::class_<H>(m, "_Simulation")
      .def(py::init(&build), py::arg("scene"), py::arg("threads") = 0, py::arg("output_directory") = "")
      .def_property_readonly("dimension", &H::dimension)
      .def("step", &H::step, py::call_guard<py::gil_scoped_release>())
      .def(
          "advance_to",
          [](H& h, double t, const py::object& poll, double poll_seconds) {
            const std::function<void()> check = python_poll(poll);
            py::gil_scoped_release release;
            h.advance_to(t, check, poll_seconds);
          },
          py::arg("t"), py::arg("poll") = py::none(), py::arg("poll_seconds") = 0.25)
      .def(
          "run",
          [](H& h, std::optional<Index> steps, Index every, const py::object& callback, const py::object& poll,
             double poll_seconds) {
            RunControl control;
            control.steps = steps;
            control.every = every;
            control.poll_seconds = poll_seconds;
            // The callbacks run with the interpreter lock; an exception they raise ends the run.
            if (!callback.is_none())
              control.callback = [&callback] {
                py::gil_scoped_acquire gil;
                const py::object result = callback();
                const int stop = PyObject_IsTrue(result.ptr());
                if (stop < 0) throw py::error_already_set();
                return stop == 1;
              };
            control.poll = python_poll(poll);
            py::gil_scoped_release release;
            return h.run(control);
          },
          py::arg("steps") = py::none(), py::arg("every") = 1, py::arg("callback") = py::none(),
          py::arg("poll") = py::none(), py::arg("poll_seconds") = 0.25)
      .def_property_readonly("time", &H::time)
      .def_property_readonly("step_count", &H::step_count)
      .def_property_readonly("dt", &H::dt)
      .def_property_readonly("end_time", &H::end_time)
      .def_property_readonly("finished", &H::finished)
      .def_property_readonly("stable_time_step", &H::stable_time_step)
      .def_property_readonly("particle_count", &H::particle_count)
      .def("energy", [](const H& h) { return energy_dict(h.energy()); })
      .def("removed",
           [](const H& h) {
             py::dict d;
             for (const RemovedTotals& r : h.removed()) {
               py::dict e = energy_dict(r.energy);
               e["particles"] = static_cast<std::int64_t>(r.particles);
               d[py::str(r.name)] = e;
             }
             return d;
           })
      .def("write_frame", &H::write_frame, py::arg("directory"), py::call_guard<py::gil_scoped_release>())
      .def_property_readonly("output_directory", &H::output_directory)
      .def("history_names", &H::history_names)
      .def("history_columns", &H::history_columns)
      .def("history_rows",
           [](const H& h, std::size_t k) {  // a new (rows, columns) array; no data is NaN
             const std::vector<double> values = h.history_rows(k);
             const auto columns = static_cast<py::ssize_t>(h.history_columns(k).size());
             py::array_t<double> a({static_cast<py::ssize_t>(values.size()) / columns, columns});
             std::copy(values.begin(), values.end(), a.mutable_data());
             return a;
           })
      .def("body_names", &H::body_names)
      .def("body_size", &H::body_size)
      .def("particle_fields", &H::particle_fields)
      .def("particle_field",
           [](const py::object& self, int body, const std::string& name) {
             return array_over(self.cast<H&>().particle_field(body, name), self);
           })
      .def("field_writable",
           [](H& h, int body, const std::string& name) { return h.particle_field(body, name).writable; })
      .def("generation", &H::generation)
      .def("output_values",
           [](const H& h, int body, const std::string& name) {
             int components = 1;
             std::vector<double> values = h.output_values(body, name, components);
             py::array_t<double> a(values.size());
             std::copy(values.begin(), values.end(), a.mutable_data());
             if (components > 1)
               return py::array_t<double>(a.reshape(
                   {static_cast<py::ssize_t>(values.size()) / components, static_cast<py::ssize_t>(components)}));
             return a;
           })
      .def("mark_changed", &H::mark_changed)
      .def("grid_info",
           [](const H& h) {
             const GridInfo g = h.grid_info();
             return py::make_tuple(g.origin, g.cell_size, g.nodes);
           })
      .def("grid_fields", &H::grid_fields)
      .def("grid_field_address",
           [](H& h, const std::string& name) {
             return reinterpret_cast<std::uintptr_t>(h.grid_field(name).storage.data);
           })
      .def("grid_field", [](const py::object& self, const std::string& name) {
        return array_over(self.cast<H&>().grid_field(name), self);
      });
}

}  // namespace
}  // namespace mpm::python

PYBIND11_MODULE(_mpm, m) {
  using namespace mpm::python;
  m.doc() = "The C++ engine behind the mpm package (use `import mpm`).";
  mpm::app::register_modules();  // the modules' material models, scene sections and output fields
  m.attr("version") = MPM_VERSION;
  m.def("compiled_modules", &mpm::app::compiled_modules, "The optional modules compiled into this build.");
  m.def(
      "output_fields",
      [] {
        std::vector<py::tuple> out;
        for (const auto& name : mpm::output_field_names()) {
          const mpm::OutputField* f = mpm::find_output_field(name);
          out.push_back(py::make_tuple(f->name, f->components, f->unit, f->description));
        }
        return out;
      },
      "(name, components, unit, description) of every output field.");
  translate_exceptions();
  bind_scene(m);
  bind_simulation(m);
}

// The Python module `dymesh` (pybind11 + numpy) over the C++ API: scenario runs, their bodies and
// summary, the force-provider loop, and numpy views of vertices and deformation that keep their run
// alive. Engine errors become Python exceptions carrying the engine's message.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <tbb/global_control.h>

#include <climits>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <unordered_set>
#include <vector>

#include "dymesh/accel/embree_locator.h"
#include "dymesh/analysis/summary.h"
#include "dymesh/core/simulation.h"
#include "dymesh/io/body_models.h"
#include "dymesh/io/output_folder.h"
#include "dymesh/io/scenario_json.h"
#include "dymesh/io/summary_json.h"
#include "dymesh/report/output_files.h"

namespace py = pybind11;

namespace {

using dymesh::RigidState;
using dymesh::Vec3;

// a state row: x, y, z, roll, pitch, yaw, vx, vy, vz, p, q, r (SI, earth frame; rates in body axes)
constexpr int kStateColumns = 12;
// a loads row: force (body), moment (body), force (earth)
constexpr int kLoadColumns = 9;
// the deepest nesting a scenario dict may have (a scenario file's is 6 or so; deeper values crashed
// the checks that walk it)
constexpr int kMaxNesting = 200;

std::unique_ptr<tbb::global_control> thread_limit;

// one scenario run (world mode, or force-provider mode driven from Python)
class Run {
 public:
  explicit Run(const dymesh::Scenario& scenario)
      : sim_(scenario, dymesh::BuildBodyModels(scenario),
             dymesh::accel::MakeEmbreeLocatorFactory(std::make_shared<const dymesh::accel::EmbreeDevice>())) {}

  // every access is refused while this run steps with the interpreter released (Stepping), from
  // another thread: it would read or change a step in progress
  dymesh::Simulation& sim() {
    RequireIdle();
    return sim_;
  }
  const dymesh::Simulation& sim() const {
    RequireIdle();
    return sim_;
  }

  // steps the run with the interpreter released while each step runs (other Python threads go on, and
  // runs in several threads step at once), until `more` (called between steps, the interpreter held)
  // says stop. Each call takes and leaves the interpreter, so `busy_` is only ever read and written
  // under it
  template <typename Step, typename More>
  void Stepping(Step&& step, More&& more) {
    RequireIdle();
    busy_ = true;
    struct Idle {
      bool& busy;
      ~Idle() { busy = false; }
    } idle{busy_};
    do {
      py::gil_scoped_release release;
      step(sim_);
    } while (more(sim_));
  }

  // the summary.json text `dymesh run` writes for this run, byte for byte
  std::string SummaryJson() const {
    const dymesh::Simulation& s = sim();
    return dymesh::SummaryJson(dymesh::Summarize(s), s.scenario(), dymesh::OutputFileNames(s.scenario()));
  }

  // states of every body as an (n, 12) array
  py::array_t<double> States() const {
    const dymesh::ContactEngine& engine = sim().engine();
    const int n = engine.body_count();
    py::array_t<double> out({n, kStateColumns});
    auto a = out.mutable_unchecked<2>();
    for (int i = 0; i < n; ++i) {
      const RigidState& r = engine.state(i).rigid;
      const double row[kStateColumns] = {r.position.x(), r.position.y(), r.position.z(), r.roll, r.pitch, r.yaw,
                                         r.velocity.x(), r.velocity.y(), r.velocity.z(), r.omega.x(), r.omega.y(),
                                         r.omega.z()};
      for (int k = 0; k < kStateColumns; ++k) a(i, k) = row[k];
    }
    return out;
  }

  // an (n, 12) array to states, refused unless it has one row per body
  std::vector<RigidState> ToStates(const py::array_t<double, py::array::c_style | py::array::forcecast>& states) const {
    const int n = sim().engine().body_count();
    if (states.ndim() != 2 || states.shape(0) != n || states.shape(1) != kStateColumns)
      throw std::invalid_argument("states: expected an array of shape (" + std::to_string(n) + ", 12), one row per body");
    auto a = states.unchecked<2>();
    std::vector<RigidState> out(n);
    for (int i = 0; i < n; ++i) {
      out[i].position = Vec3(a(i, 0), a(i, 1), a(i, 2));
      out[i].roll = a(i, 3), out[i].pitch = a(i, 4), out[i].yaw = a(i, 5);
      out[i].velocity = Vec3(a(i, 6), a(i, 7), a(i, 8));
      out[i].omega = Vec3(a(i, 9), a(i, 10), a(i, 11));
    }
    return out;
  }

  // ends a host-driven run, refused before its first host step (it read "complete" with 0 steps)
  void HostFinish(const py::array_t<double, py::array::c_style | py::array::forcecast>& states) {
    dymesh::Simulation& s = sim();
    if (!s.finished() && s.steps() == 0)
      throw std::logic_error("no host step taken: a host-driven run ends after its first host_step");
    s.FinishHostRun(ToStates(states));
  }

  // writes the outputs into `dir`, the summary's text made first: a run it cannot describe writes
  // nothing (WriteOutputs makes it last, after the meshes)
  void WriteOutputs(const std::string& dir) const {
    const dymesh::Simulation& s = sim();
    const dymesh::Summary summary = dymesh::Summarize(s);
    dymesh::SummaryJson(summary, s.scenario(), dymesh::OutputFileNames(s.scenario()));
    dymesh::OutputFolder folder(dir, dymesh::OutputFileNames(s.scenario()), dymesh::InputFiles(s.scenario()), "dir");
    folder.ReplacePreviousRun();
    dymesh::WriteOutputs(s, summary, dir);
  }

  // force-provider step: loads (n, 9) for the coming step
  py::array_t<double> HostStep(const py::array_t<double, py::array::c_style | py::array::forcecast>& states,
                               const py::object& dt_seconds) {
    // a number, not a bool (True was taken as a step of 1 s)
    const bool is_bool = PyBool_Check(dt_seconds.ptr()) || py::isinstance(dt_seconds, py::module_::import("numpy").attr("bool_"));
    if (is_bool || !PyNumber_Check(dt_seconds.ptr()) || py::isinstance<py::str>(dt_seconds))
      throw py::type_error("dt: expected a number of seconds, got " +
                           (is_bool ? std::string("bool") : std::string(Py_TYPE(dt_seconds.ptr())->tp_name)) + " (" +
                           py::repr(dt_seconds).cast<std::string>() + ")");
    const double dt = PyFloat_AsDouble(dt_seconds.ptr());
    if (PyErr_Occurred()) throw py::error_already_set();
    const std::vector<RigidState> at = ToStates(states);
    dymesh::StepResult step;
    Stepping([&](dymesh::Simulation& sim) { step = sim.HostStep(at, dt); }, [](const dymesh::Simulation&) { return false; });
    const int n = sim_.engine().body_count();
    py::array_t<double> out({n, kLoadColumns});
    auto a = out.mutable_unchecked<2>();
    for (int i = 0; i < n; ++i)
      for (int k = 0; k < 3; ++k) {
        a(i, k) = step.loads[i].force_body[k];
        a(i, 3 + k) = step.loads[i].moment_body[k];
        a(i, 6 + k) = step.loads[i].force_earth[k];
      }
    return out;
  }

 private:
  void RequireIdle() const {
    if (busy_) throw std::logic_error("the run is stepping in another thread: wait until its run() returns");
  }

  dymesh::Simulation sim_;
  bool busy_ = false;  // stepping with the interpreter released
};

// a read-only (rows, 3) view into engine memory that keeps `owner` (the Run) alive
py::array_t<double> View(const std::vector<Vec3>& data, py::handle owner) {
  py::array_t<double> a({static_cast<py::ssize_t>(data.size()), py::ssize_t{3}},
                        {static_cast<py::ssize_t>(sizeof(Vec3)), static_cast<py::ssize_t>(sizeof(double))},
                        data.empty() ? nullptr : data.front().data(), owner);
  a.attr("setflags")(py::arg("write") = false);
  return a;
}

// one body of a run, by index
struct Body {
  py::object run;  // keeps the Run alive
  int index;
  const dymesh::Simulation& sim() const { return run.cast<const Run&>().sim(); }
};

// a path argument: str, bytes or os.PathLike, as the system is given it (os.fsencode: a str's
// undecodable bytes kept), refused when it holds a NUL (the path would be cut short at it)
std::string PathArgument(const py::object& path, const char* argument) {
  const py::module_ os = py::module_::import("os");
  if (!py::isinstance<py::str>(path) && !py::isinstance<py::bytes>(path) && !py::isinstance(path, os.attr("PathLike")))
    throw py::type_error(std::string(argument) + ": expected str, bytes or os.PathLike, got " + Py_TYPE(path.ptr())->tp_name);
  const std::string bytes = os.attr("fsencode")(path).cast<py::bytes>();
  if (bytes.find('\0') != std::string::npos)
    throw std::invalid_argument(std::string(argument) + ": a file name cannot hold a NUL character");
  return bytes;
}

// a scenario dict checked before json.dumps turns it into text, each refusal naming the path: a
// non-finite float (written as NaN or Infinity, which the JSON reader refuses only by byte offset), a
// str that is not UTF-8 (a lone surrogate: likewise), a container holding itself or nested past
// kMaxNesting (the walk recursed without end: a crash, a sweep 2026-11-28)
class ScenarioTree {
 public:
  explicit ScenarioTree(std::string file) : file_(std::move(file)) {}

  void Check(const py::handle& value, const std::string& path, int depth) {
    const std::string at = path.empty() ? "(root)" : path;
    if (py::isinstance<py::float_>(value) && !std::isfinite(value.cast<double>()))
      throw dymesh::InputError(file_, at, "expected a finite number, got " + py::repr(value).cast<std::string>());
    if (py::isinstance<py::str>(value)) {
      Py_ssize_t size = 0;
      if (PyUnicode_AsUTF8AndSize(value.ptr(), &size) == nullptr) {
        PyErr_Clear();
        throw dymesh::InputError(file_, at, "expected UTF-8 text, got a str holding a lone surrogate");
      }
      return;
    }
    const bool dict = py::isinstance<py::dict>(value);
    if (!dict && !py::isinstance<py::list>(value) && !py::isinstance<py::tuple>(value)) return;
    // a container: once (one held in two places is checked where first met), not inside itself,
    // not too deep
    if (checked_.count(value.ptr())) return;
    if (open_.count(value.ptr()))
      throw dymesh::InputError(file_, at, "refers back to a value that holds it (a cycle): expected JSON data, a tree");
    if (depth > kMaxNesting)
      throw dymesh::InputError(file_, at, "expected values nested at most " + std::to_string(kMaxNesting) + " deep");
    open_.insert(value.ptr());
    if (dict) {
      for (const auto& item : value.cast<py::dict>())
        Check(item.second, (path.empty() ? "" : path + ".") + py::str(item.first).cast<std::string>(), depth + 1);
    } else {
      std::size_t i = 0;
      for (const auto& item : value) Check(item, path + "[" + std::to_string(i++) + "]", depth + 1);
    }
    open_.erase(value.ptr());
    checked_.insert(value.ptr());
  }

 private:
  std::string file_;
  std::unordered_set<PyObject*> open_, checked_;  // containers being walked, and walked (the caller's dict holds them)
};

int CheckedIndex(const Run& run, int index) {
  const int n = run.sim().engine().body_count();
  if (index < 0 || index >= n) throw py::index_error("body " + std::to_string(index) + " is out of range 0.." + std::to_string(n - 1));
  return index;
}

}  // namespace

PYBIND11_MODULE(dymesh, m) {
  m.doc() = "DyMESH mesh-based vehicle collision engine: scenario runs and the force-provider loop";
  static py::exception<dymesh::InputError> input_error(m, "InputError", PyExc_ValueError);
  // a call that does not fit the run's state (stepping a finished run, mixing its own steps with
  // host steps), as the C ABI's DM_ERROR_STATE
  static py::exception<std::logic_error> state_error(m, "StateError", PyExc_RuntimeError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const dymesh::InputError& e) {
      input_error(e.what());
    } catch (const std::invalid_argument&) {
      throw;  // ValueError (pybind11's own translation)
    } catch (const std::out_of_range&) {
      throw;  // IndexError
    } catch (const std::length_error&) {
      throw;  // ValueError
    } catch (const std::logic_error& e) {
      state_error(e.what());
    }
  });

  m.def("set_threads", [](const py::object& count) {
    // an int of any size (2**40 was pybind11's TypeError), not a bool or a float
    if (PyBool_Check(count.ptr()) || !PyIndex_Check(count.ptr()))
      throw py::type_error(std::string("threads: expected an int, got ") + Py_TYPE(count.ptr())->tp_name);
    PyObject* index = PyNumber_Index(count.ptr());
    if (index == nullptr) throw py::error_already_set();
    const py::int_ value = py::reinterpret_steal<py::int_>(index);
    int overflow = 0;
    const long long wanted = PyLong_AsLongLongAndOverflow(value.ptr(), &overflow);
    if (overflow != 0 || wanted < 0 || wanted > 4096)
      throw std::invalid_argument("threads: expected 0 (all cores) .. 4096, got " + py::repr(value).cast<std::string>());
    const int threads = static_cast<int>(wanted);
    thread_limit.reset();
    if (threads > 0) thread_limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, threads);
  }, py::arg("threads"), "Limits the worker threads (0: all cores); results do not depend on it.");

  py::class_<Body>(m, "Body", "One body of a run.")
      .def_property_readonly("name", [](const Body& b) { return b.sim().engine().model(b.index).name; })
      .def_property_readonly("delta_v", [](const Body& b) {
        const dymesh::Simulation& sim = b.sim();
        const Vec3 dv = (sim.engine().state(b.index).rigid.velocity - sim.history().front().bodies[b.index].rigid.velocity) *
                        dymesh::UnitsOf(sim.scenario().units).speed;
        return py::array_t<double>(3, dv.data());
      }, "Delta-V since t = 0, earth frame, in the scenario's units (mph or m/s).")
      .def_property_readonly("mass", [](const Body& b) { return b.sim().engine().model(b.index).mass; }, "[kg]")
      .def_property_readonly("inertia", [](const Body& b) {
        const dymesh::Mat3& i = b.sim().engine().model(b.index).inertia;
        py::array_t<double> out({3, 3});
        auto a = out.mutable_unchecked<2>();
        for (int r = 0; r < 3; ++r)
          for (int c = 0; c < 3; ++c) a(r, c) = i(r, c);
        return out;
      }, "[kg m^2] about the CG, body axes")
      .def_property_readonly("crush", [](const Body& b) {
        const std::vector<double> c = dymesh::VertexCrush(b.sim(), b.index);
        return py::array_t<double>(static_cast<py::ssize_t>(c.size()), c.data());
      }, "Permanent crush |Delta| per vertex [m] (a copy).")
      .def_property_readonly("vertices", [](const Body& b) { return View(b.sim().engine().state(b.index).vertices, b.run); },
                             "Current vertices, body frame [m]: a read-only view that follows the run.")
      .def_property_readonly("deformation", [](const Body& b) { return View(b.sim().engine().state(b.index).delta, b.run); },
                             "Permanent deformation Delta per vertex, body frame [m]: a read-only view.");

  py::class_<Run>(m, "Run", "A scenario run: world mode (run, step) or force-provider mode (host_step).")
      .def("run", [](py::object self) {
             Run& r = self.cast<Run&>();
             // Ctrl-C (or any signal Python handles) stops the run between steps, its state consistent
             // and unfinished (status "interrupted"), and raises there (KeyboardInterrupt)
             bool signalled = false, more = true;
             r.Stepping([&](dymesh::Simulation& sim) { more = sim.Advance(); },
                        [&](const dymesh::Simulation&) { return more && !(signalled = PyErr_CheckSignals() != 0); });
             if (signalled) throw py::error_already_set();
             return self;
           }, "Runs to the end (duration or separation); returns the run. StateError for a finished or host-driven "
              "run; a Ctrl-C stops it between steps (KeyboardInterrupt; the run stays unfinished, status "
              "\"interrupted\"). Other threads run while it steps; any other call on this run meanwhile raises "
              "StateError.")
      .def("step", [](Run& r) {
             r.Stepping([](dymesh::Simulation& sim) { sim.Advance(); }, [](const dymesh::Simulation&) { return false; });
             return r.sim().finished();
           }, "One step; True once the run has ended. StateError for a finished or host-driven run.")
      .def_property_readonly("time", [](const Run& r) { return r.sim().time(); })
      .def_property_readonly("finished", [](const Run& r) { return r.sim().finished(); })
      .def_property_readonly("status", [](const Run& r) { return std::string(dymesh::RunStatusName(dymesh::Summarize(r.sim()).status)); })
      .def_property_readonly("bodies", [](py::object self) {
        const Run& r = self.cast<const Run&>();
        py::list out;
        for (int i = 0; i < r.sim().engine().body_count(); ++i) out.append(Body{self, i});
        return out;
      })
      .def("body", [](py::object self, int i) { return Body{self, CheckedIndex(self.cast<const Run&>(), i)}; })
      .def_property_readonly("summary_json", &Run::SummaryJson, "summary.json text, byte-identical to `dymesh run`'s.")
      .def_property_readonly("summary", [](const Run& r) { return py::module_::import("json").attr("loads")(r.SummaryJson()); },
                             "The summary as a dict.")
      .def("states", &Run::States, "Every body's state, shape (n, 12): x y z roll pitch yaw vx vy vz p q r (SI).")
      .def("host_step", &Run::HostStep, py::arg("states"), py::arg("dt"),
           "Force-provider step: every body's state now (n, 12); returns the loads (n, 9) for the coming step: "
           "force (body), moment (body), force (earth).")
      .def("host_finish", &Run::HostFinish, py::arg("states"),
           "Ends a host-driven run with the states reached after the last step. StateError before the first "
           "host_step.")
      .def("write_outputs", [](const Run& r, const py::object& dir) { r.WriteOutputs(PathArgument(dir, "dir")); },
           py::arg("dir"), "Writes meshes, history.csv, report.html and summary.json into `dir` (str or os.PathLike).");

  m.def("load_scenario", [](const py::object& path) {
          return std::make_unique<Run>(dymesh::LoadScenario(PathArgument(path, "path")));
        },
        py::arg("path"), "Loads and validates a scenario file (str or os.PathLike) and its meshes; returns a Run.");
  m.def("scenario", [](const py::object& scenario, const py::object& base_dir) {
          // a dict is the scenario file's JSON; a str its text. Relative mesh and vehicle paths resolve
          // against base_dir; errors name the field as for a file
          const std::string file = PathArgument(base_dir, "base_dir") + "/(python scenario)";
          if (!py::isinstance<py::str>(scenario)) ScenarioTree(file).Check(scenario, "", 0);
          std::string text;
          if (py::isinstance<py::str>(scenario)) {
            Py_ssize_t size = 0;
            const char* utf8 = PyUnicode_AsUTF8AndSize(scenario.ptr(), &size);
            if (utf8 == nullptr) {
              PyErr_Clear();
              throw dymesh::InputError(file, "(json)", "expected UTF-8 text, got a str holding a lone surrogate");
            }
            text.assign(utf8, static_cast<std::size_t>(size));
          } else {
            text = py::module_::import("json").attr("dumps")(scenario).cast<std::string>();
          }
          return std::make_unique<Run>(dymesh::ParseScenario(text, file));
        },
        py::arg("scenario"), py::arg("base_dir") = ".",
        "Builds a Run from a scenario given as a dict (or JSON text), laid out as a scenario file: bodies, "
        "meshes (files, boxes, cylinders), motion, contact options. Relative paths resolve against base_dir "
        "(str or os.PathLike).");
}

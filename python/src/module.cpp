// The extension module mbc._mbc: what the Python package (python/mbc)
// builds on. Compiling, contexts and runs; the Python side makes the API
// (exceptions, keyword arguments, DataFrames).
#include <mbc/version.h>

#include <csignal>
#include <cstring>
#include <dlfcn.h>
#include <optional>
#include <pybind11/stl.h>
#include <thread>

#include "batch_rows.h"
#include "compiled_program.h"
#include "program_run.h"
#include "runner/interrupt_scope.h"
#include "runner/run_session.h"

namespace py = pybind11;
using namespace mbc::python;

namespace {

/// Code the JIT loads calls the runtime by name (toolchain/native_code.h);
/// Python loads extensions with their symbols private, so this module
/// makes its own (the runtime's C ABI, src/exports.map) global once.
void exportRuntime() {
  Dl_info self{};
  if (dladdr(reinterpret_cast<void*>(&mbrt_create), &self) == 0 ||
      dlopen(self.dli_fname, RTLD_NOW | RTLD_NOLOAD | RTLD_GLOBAL) == nullptr) {
    throw std::runtime_error(
        "mbc: cannot make the runtime visible to compiled code");
  }
}

/// Ctrl-C during a run: Python's own handler only notes the signal for
/// when the interpreter runs again, which it does not while compiled code
/// loops. This one stops the runs going on (alarm MBC0004) and passes the
/// signal on to Python's, so that the call then raises KeyboardInterrupt.
/// A handler Python code installs later replaces it (and runs are then
/// stopped by their block limit only).
struct sigaction pythonSigint {};

void onSigint(int sig, siginfo_t* info, void* context) {
  mbc::runner::interruptRuns();
  if ((pythonSigint.sa_flags & SA_SIGINFO) != 0) {
    pythonSigint.sa_sigaction(sig, info, context);
  } else if (pythonSigint.sa_handler != SIG_DFL &&
             pythonSigint.sa_handler != SIG_IGN) {
    pythonSigint.sa_handler(sig);
  } else if (pythonSigint.sa_handler == SIG_DFL) {
    std::signal(sig, SIG_DFL);
    std::raise(sig);
  }
}

void stopRunsOnSigint() {
  struct sigaction action {};

  action.sa_sigaction = onSigint;
  action.sa_flags = SA_SIGINFO | SA_RESTART;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, &pythonSigint);
}

/// After a run a signal stopped: the KeyboardInterrupt Python's handler
/// asked for, rather than the alarm.
void raisePendingSignal() {
  if (PyErr_CheckSignals() != 0) {
    throw py::error_already_set();
  }
}

/// A machine: one runtime context, used by one thread at a time (the
/// Python side holds the GIL around everything but the run).
class Context {
public:
  explicit Context(const std::optional<std::string>& profile) {
    std::string error;
    ctx_ = newContext(profile ? &*profile : nullptr, error);
    if (!ctx_) {
      throw py::value_error(error);
    }
    axes_ = axisNames(ctx_.get());
  }

  /// The context, for a call under the GIL.
  mbrt_ctx* get() const {
    // Another Python thread is in a run, which released the GIL: a context
    // is one thread's at a time.
    if (running) {
      throw std::runtime_error(
          "mbc: this Machine is running a program in another thread; use "
          "one Machine per thread");
    }
    return ctx_.get();
  }

  const std::string& axes() const { return axes_; }

  NameTable& programs() { return programs_; }

  NameTable& files() { return files_; }

  std::size_t lastMotions = 0; // how many the last run made
  bool running = false;        // set and read under the GIL

private:
  mbc::runner::CtxPtr ctx_;
  std::string axes_;
  NameTable programs_, files_; // of all its runs' motions
};

/// Marks a context as running for as long as it lives (an exception too
/// ends the run).
struct Running {
  explicit Running(Context& c) : context(c) { context.running = true; }

  ~Running() { context.running = false; }

  Running(const Running&) = delete;
  Running& operator=(const Running&) = delete;
  Context& context;
};

/// A Machine's callbacks during one run, called under the GIL as the run
/// goes. The first exception one raises stops the run before its next
/// block (as Ctrl-C does), and the call raises it.
struct PythonWatchers {
  py::object motion, print, alarm, motionNames;
  const RunOutput* out = nullptr;
  mbrt_ctx* ctx = nullptr;
  std::optional<py::error_already_set> error;

  template <class Call> void call(Call&& c) {
    if (error) {
      return;
    }
    const py::gil_scoped_acquire gil;
    try {
      c();
    } catch (py::error_already_set& e) {
      error.emplace(std::move(e));
      mbrt_interrupt(ctx);
    } catch (const std::exception& e) {
      // Nothing may unwind through the runtime's frames.
      PyErr_SetString(PyExc_RuntimeError, e.what());
      error.emplace();
      mbrt_interrupt(ctx);
    }
  }

  static PythonWatchers& of(void* user) {
    return *static_cast<PythonWatchers*>(user);
  }

  static void onMotion(void* user) {
    PythonWatchers& w = of(user);
    w.call([&] { w.motion(w.out->motions.lastRow(w.motionNames)); });
  }

  static void onPrint(void* user, const char* data, std::size_t size) {
    PythonWatchers& w = of(user);
    w.call([&] { w.print(py::str(data, size)); });
  }

  static void onAlarm(void* user, const char* data, std::size_t size) {
    PythonWatchers& w = of(user);
    w.call([&] { w.alarm(py::str(data, size)); });
  }

  /// The watchers a request gets: none when no callback is set.
  RunWatchers watchers() {
    if (motion.is_none() && print.is_none() && alarm.is_none()) {
      return {};
    }
    return {motion.is_none() ? nullptr : &onMotion,
            print.is_none() ? nullptr : &onPrint,
            alarm.is_none() ? nullptr : &onAlarm, this};
  }
};

RunRequest request(const std::string& letters,
                   const std::vector<double>& values,
                   const std::vector<std::pair<double, double>>& presets,
                   std::uint64_t maxBlocks) {
  if (letters.size() != values.size()) {
    throw py::value_error("one value per argument letter");
  }
  RunRequest r;
  for (std::size_t i = 0; i < letters.size(); ++i) {
    r.args.emplace_back(letters[i], values[i]);
  }
  r.presets = presets;
  r.maxBlocks = maxBlocks;
  return r;
}

py::object alarmData(const std::optional<AlarmParts>& alarm) {
  if (!alarm) {
    return py::none();
  }
  py::dict d;
  d["number"] = alarm->number;
  d["code"] = alarm->code;
  d["message"] = alarm->message;
  d["file"] = alarm->file;
  d["line"] = alarm->line;
  d["report"] = alarm->report;
  d["call_stack"] = alarm->calls;
  return d;
}

/// A finished run as Python sees it: each part becomes a Python object
/// only when asked for (a simulation loop reads two or three of them).
struct RunResult {
  explicit RunResult(std::unique_ptr<RunOutput> run) : out(std::move(run)) {}

  py::object motions() {
    if (!array) {
      array = out->motions.take();
    }
    return array;
  }

  py::dict box() const {
    py::dict box;
    const mbrt_stats& st = out->stats;
    for (int axis = 0; st.moves > 0 && axis < st.axis_count; ++axis) {
      box[py::str(out->axes.substr(static_cast<std::size_t>(axis), 1))] =
          py::make_tuple(st.box_min[axis], st.box_max[axis]);
    }
    return box;
  }

  std::unique_ptr<RunOutput> out;
  py::object array;
};

} // namespace

PYBIND11_MODULE(_mbc, m) {
  m.doc() = "The compiled core of the mbc package (use the mbc module).";
  exportRuntime();
  stopRunsOnSigint();
  m.attr("__version__") = MBC_VERSION_STRING;

  py::class_<CompiledProgram>(m, "CompiledProgram")
      .def_property_readonly("main", &CompiledProgram::mainName)
      .def_property_readonly("programs", &CompiledProgram::programs);

  m.def(
      "compile",
      [](const std::vector<std::pair<std::string, std::string>>& texts,
         const std::vector<std::string>& files, const std::string& main,
         int opt, bool cache, bool strict, bool defaultMachine,
         const std::vector<std::string>& includeDirs) {
        CompileRequest r;
        for (const auto& [name, text] : texts) {
          r.texts.push_back({name, text});
        }
        r.files = files;
        r.main = main;
        r.opt = opt;
        r.cache = cache;
        r.strict = strict;
        r.defaultMachine = defaultMachine;
        r.includeDirs = includeDirs;
        py::list diagnostics;
        std::string message;
        auto compiled = CompiledProgram::compile(r, diagnostics, message);
        return py::make_tuple(py::cast(std::move(compiled)), diagnostics,
                              message);
      },
      py::arg("texts"), py::arg("files"), py::arg("main"), py::arg("opt"),
      py::arg("cache"), py::arg("strict"), py::arg("default_machine"),
      py::arg("include_dirs"));

  py::class_<RunResult>(m, "RunOutput")
      .def_property_readonly("main",
                             [](const RunResult& r) { return r.out->main; })
      .def_property_readonly("status",
                             [](const RunResult& r) { return r.out->status; })
      .def_property_readonly(
          "alarm", [](const RunResult& r) { return alarmData(r.out->alarm); })
      .def_property_readonly("programs",
                             [](const RunResult& r) {
                               return py::tuple(py::cast(r.out->programs));
                             })
      .def_property_readonly(
          "files",
          [](const RunResult& r) { return py::tuple(py::cast(r.out->files)); })
      .def_property_readonly("motions", &RunResult::motions)
      .def_property_readonly("dprnt",
                             [](const RunResult& r) { return r.out->dprnt; })
      .def_property_readonly("messages",
                             [](const RunResult& r) { return r.out->messages; })
      .def_property_readonly("variables",
                             [](const RunResult& r) {
                               py::dict d;
                               for (const auto& [n, v] : r.out->variables) {
                                 d[py::int_(n)] = v;
                               }
                               return d;
                             })
      .def_property_readonly(
          "blocks", [](const RunResult& r) { return r.out->stats.blocks; })
      .def_property_readonly(
          "moves", [](const RunResult& r) { return r.out->stats.moves; })
      .def_property_readonly(
          "optional_stops",
          [](const RunResult& r) { return r.out->stats.optional_stops; })
      .def_property_readonly(
          "main_m99",
          [](const RunResult& r) { return r.out->stats.main_m99 != 0; })
      .def_property_readonly("unit",
                             [](const RunResult& r) { return r.out->unit; })
      .def_property_readonly(
          "feed_length",
          [](const RunResult& r) { return r.out->stats.feed_length; })
      .def_property_readonly(
          "rapid_length",
          [](const RunResult& r) { return r.out->stats.rapid_length; })
      .def_property_readonly(
          "cycle_time",
          [](const RunResult& r) { return r.out->stats.cycle_time; })
      .def_property_readonly("box", &RunResult::box);

  py::class_<Context>(m, "Context")
      .def(py::init<const std::optional<std::string>&>(), py::arg("profile"))
      .def(
          "run",
          [](Context& c, const CompiledProgram& program,
             const std::string& letters, const std::vector<double>& values,
             const std::vector<std::pair<double, double>>& presets,
             std::uint64_t maxBlocks, const py::object& onMotion,
             const py::object& onPrint, const py::object& onAlarm,
             const py::object& motionNames) {
            auto out =
                std::make_unique<RunOutput>(c.axes(), c.programs(), c.files());
            out->motions.reserve(c.lastMotions);
            RunRequest r = request(letters, values, presets, maxBlocks);
            mbrt_ctx* ctx = c.get();
            PythonWatchers watchers{onMotion,    onPrint,   onAlarm,
                                    motionNames, out.get(), ctx,
                                    std::nullopt};
            r.watch = watchers.watchers();
            {
              const Running busy(c);
              py::gil_scoped_release unlocked;
              const mbc::runner::InterruptibleRun interruptible(ctx);
              runProgram(program, ctx, r, *out);
            }
            if (watchers.error) {
              throw std::move(*watchers.error);
            }
            if (out->status == MBRT_ALARM_Interrupted) {
              raisePendingSignal();
            }
            c.lastMotions = out->motions.size();
            return RunResult(std::move(out));
          },
          py::arg("program"), py::arg("letters"), py::arg("values"),
          py::arg("presets"), py::arg("max_blocks"),
          py::arg("on_motion") = py::none(), py::arg("on_print") = py::none(),
          py::arg("on_alarm") = py::none(),
          py::arg("motion_names") = py::none())
      .def("read",
           [](Context& c, double number) -> py::object {
             mbrt_num value;
             if (mbrt_read_var(c.get(), number, &value) != MBRT_OK) {
               throw py::key_error(std::to_string(number));
             }
             if (mbc::isVacant(value)) {
               return py::none();
             }
             return py::float_(value);
           })
      .def("write",
           [](Context& c, double number, std::optional<double> value) {
             const mbrt_status st = mbrt_preset_var(
                 c.get(), number, value ? *value : mbc::vacant());
             if (st != MBRT_OK) {
               char report[512];
               mbrt_alarm_report(c.get(), report, sizeof report);
               throw py::value_error(report);
             }
           })
      .def("get_position",
           [](Context& c, int axis) {
             double value = 0.0;
             mbrt_get_machine_position(c.get(), axis, &value);
             return value;
           })
      .def("set_position",
           [](Context& c, int axis, double value) {
             if (mbrt_set_machine_position(c.get(), axis, value) == 0) {
               throw py::value_error(
                   "position " + std::to_string(value) +
                   ": more than nine digits, or not a number");
             }
           })
      .def("reset", [](Context& c) { mbrt_reset(c.get()); })
      .def("reset_state", [](Context& c) { mbrt_reset_state(c.get()); })
      .def_property_readonly("axes", &Context::axes);

  m.def("motion_dtype", &MotionTable::rowType, py::arg("axes"));
  m.def(
      "concatenate",
      [](const std::vector<py::array>& arrays) {
        if (arrays.empty()) {
          throw py::value_error("no arrays to concatenate");
        }
        const py::dtype dtype = arrays.front().dtype();
        py::ssize_t rows = 0;
        for (const py::array& a : arrays) {
          if (!a.dtype().is(dtype) && !a.dtype().equal(dtype)) {
            throw py::value_error("the arrays are not all of one machine's "
                                  "motions");
          }
          if (a.ndim() != 1 || (a.flags() & py::array::c_style) == 0) {
            throw py::value_error("a motions array must be 1-D and contiguous");
          }
          rows += a.shape(0);
        }
        py::array out(dtype, std::vector<py::ssize_t>{rows});
        auto* to = static_cast<char*>(out.mutable_data());
        for (const py::array& a : arrays) {
          const auto bytes = static_cast<std::size_t>(a.nbytes());
          if (bytes > 0) {
            std::memcpy(to, a.data(), bytes);
          }
          to += bytes;
        }
        return out;
      },
      py::arg("arrays"));

  m.def(
      "run_rows",
      [](const CompiledProgram& program,
         const std::optional<std::string>& profile,
         const std::vector<std::tuple<std::string, std::vector<double>,
                                      std::vector<std::pair<double, double>>>>&
             rows,
         unsigned threads, std::uint64_t maxBlocks) {
        std::vector<RunRequest> requests;
        for (const auto& [letters, values, presets] : rows) {
          requests.push_back(request(letters, values, presets, maxBlocks));
        }
        std::vector<std::unique_ptr<RunOutput>> outputs;
        std::string error;
        bool ok = false;
        {
          py::gil_scoped_release unlocked;
          ok = runRows(program, profile ? &*profile : nullptr, requests,
                       threads != 0 ? threads
                                    : std::thread::hardware_concurrency(),
                       outputs, error);
        }
        if (!ok) {
          throw py::value_error(error);
        }
        // The rows a signal let finish stay: the caller gets them with the
        // KeyboardInterrupt Python's handler asked for (None if it asked
        // for none), and None for each row never started.
        py::list results;
        bool interrupted = false;
        for (auto& out : outputs) {
          interrupted = interrupted || out == nullptr ||
                        out->status == MBRT_ALARM_Interrupted;
          results.append(out != nullptr ? py::cast(RunResult(std::move(out)))
                                        : py::none());
        }
        py::object signal = py::none();
        if (interrupted && PyErr_CheckSignals() != 0) {
          const py::error_already_set raised;
          signal = raised.value();
        }
        return py::make_tuple(results, signal);
      },
      py::arg("program"), py::arg("profile"), py::arg("rows"),
      py::arg("threads"), py::arg("max_blocks"));
}

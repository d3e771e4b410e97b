"""mbc: FANUC Custom Macro B programs compiled to native code, from Python.

    import mbc
    pocket = mbc.compile("pocket.nc")              # or source text, or a list
    machine = mbc.Machine()                        # or Machine("mill.json")
    result = pocket(machine, X=50, Y=0, Z=-5, R=20, D=8)
    result.motions                                 # numpy structured array
    result.variables[100]                          # common variables
    mbc.batch(pocket, table)                       # a pandas DataFrame per row

A Machine keeps its state between runs as a control does (position, modal
codes, offsets, common variables); alarms raise mbc.Alarm, errors in the
source mbc.CompileError. docs/python.md has the whole story.
"""
from __future__ import annotations

import json
import os
from dataclasses import dataclass
from typing import Any, Mapping, Optional, Sequence, Union

import numpy

from . import _mbc

__version__: str = _mbc.__version__

#: The `motion` column's values, by code: 0 rapid, 1 linear, 2 cw, 3 ccw.
MOTION_NAMES = ("rapid", "linear", "cw", "ccw")

Source = Union[str, "os.PathLike[str]"]


@dataclass(frozen=True)
class FixIt:
    """A suggested edit: replace `length` bytes at file:line:column."""

    file: str
    line: int
    column: int
    length: int
    replacement: str


@dataclass(frozen=True)
class Diagnostic:
    """An error, warning or note about the source, as `mbc check` prints it."""

    severity: str
    file: str
    line: int
    column: int
    message: str
    fixits: tuple = ()
    notes: tuple = ()

    @staticmethod
    def _from(d: Mapping[str, Any]) -> "Diagnostic":
        return Diagnostic(
            d["severity"], d["file"], d["line"], d["column"], d["message"],
            tuple(FixIt(f["file"], f["line"], f["column"], f["length"],
                        f["replacement"]) for f in d["fixits"]),
            tuple(Diagnostic._from(n) for n in d["notes"]))

    def __str__(self) -> str:
        return f"{self.file}:{self.line}:{self.column}: {self.severity}: {self.message}"


class Error(Exception):
    """The base of the package's exceptions."""


class CompileError(Error):
    """The source could not be compiled. `diagnostics` holds every error and
    warning (file, line, column, message, fix-its); str() is the clang-style
    text `mbc check` prints."""

    def __init__(self, message: str, diagnostics: Sequence[Diagnostic] = ()):
        super().__init__(message)
        self.diagnostics = tuple(diagnostics)

    @property
    def errors(self) -> tuple:
        return tuple(d for d in self.diagnostics if d.severity == "error")


class Alarm(Error):
    """A run stopped with an alarm, as the control shows it.

    number: 3001 for #3000=1, 112 for PS0112, 2 for mbc's MBC0002.
    code: "3001", "PS0112", "MBC0002".  message: "ZERO DIVIDE" or the
    #3000 text.  file, line: the block.  call_stack: (program, file, line)
    of each call it happened under, innermost first.  result: the Result of
    the run up to the alarm (its motions, DPRNT...).  str(): the report
    `mbc run` prints."""

    def __init__(self, number: int, code: str, message: str, file: str,
                 line: int, call_stack: Sequence[tuple] = (),
                 report: str = "", result: Optional["Result"] = None):
        super().__init__(report.rstrip("\n") or f"alarm {code}: {message}")
        self.number = number
        self.code = code
        self.message = message
        self.file = file
        self.line = line
        self.call_stack = tuple(tuple(c) for c in call_stack)
        self.report = report
        self.result = result

    def __reduce__(self):
        return (Alarm, (self.number, self.code, self.message, self.file,
                        self.line, self.call_stack, self.report, self.result))


#: What a Result tells, by name (a property each).
_RESULT_FIELDS = ("main", "motions", "dprnt", "messages", "variables",
                  "blocks", "moves", "cycle_time", "feed_length",
                  "rapid_length", "unit", "box", "programs", "files",
                  "optional_stops", "main_m99")


class Result:
    """What a run did.

    motions: a numpy structured array, one row per motion (the fields of the
    toolpath: `motion` (see MOTION_NAMES), `line`, `prog` and `file`
    (indexes into `programs` and `files`, which a Machine numbers alike in
    all its runs: see concatenate), `cycle` (81 for G81, 0), `plane`, `f`
    (NaN for rapids), and per axis, for X: `x` the end point in the
    workpiece system, `mx` in machine coordinates, `sx` the start, `px` the
    programmed end (differs under cutter compensation), `cx` the arc centre
    (NaN off the arc plane)).  dprnt: DPRNT/BPRNT output.  messages: operator
    messages (#3006, M00/M01).  variables: the common variables set at the
    end ({number: value}).  blocks, moves, cycle_time (seconds), feed_length,
    rapid_length (in `unit`), box ({axis: (min, max)}), optional_stops,
    main_m99.  alarm: the Alarm that stopped the run, or None.

    Each part is made into a Python object when first read."""

    __slots__ = ("_raw", "_parts", "alarm")

    def __init__(self, raw):
        self._raw = raw
        self._parts = {}
        self.alarm: Optional[Alarm] = None

    @staticmethod
    def _from(raw) -> "Result":
        r = Result(raw)
        a = raw.alarm
        if a is not None:
            r.alarm = Alarm(a["number"], a["code"], a["message"], a["file"],
                            a["line"], a["call_stack"], a["report"], r)
        return r

    def __reduce__(self):
        alarm = self.alarm
        return (_restore_result,
                ({name: getattr(self, name) for name in _RESULT_FIELDS},
                 None if alarm is None else
                 (alarm.number, alarm.code, alarm.message, alarm.file,
                  alarm.line, alarm.call_stack, alarm.report)))

    def __repr__(self) -> str:
        return (f"<mbc.Result {self.main}: {self.blocks} blocks, "
                f"{self.moves} moves{'' if self.alarm is None else ', alarm'}>")

    @property
    def summary(self) -> dict:
        """The `mbc run` summary as a dict."""
        return {"main": self.main, "blocks": self.blocks, "moves": self.moves,
                "alarms": 0 if self.alarm is None else 1, "unit": self.unit,
                "feed_length": self.feed_length,
                "rapid_length": self.rapid_length,
                "cycle_time": self.cycle_time, "box": dict(self.box)}

    def motions_frame(self):
        """The motions as a pandas DataFrame (motion, prog and file as
        categories)."""
        return _motions_frame(self.motions, self.programs, self.files)


def _part(name: str) -> property:
    def get(self):
        parts = self._parts
        if name not in parts:
            parts[name] = getattr(self._raw, name)
        return parts[name]
    return property(get, doc=f"The run's {name} (see Result).")


for _name in _RESULT_FIELDS:
    setattr(Result, _name, _part(_name))


def _restore_result(parts: dict, alarm) -> Result:
    """A Result unpickled: its parts as they were, no run behind them."""
    r = Result(None)
    r._parts = dict(parts)
    if alarm is not None:
        r.alarm = Alarm(*alarm, result=r)
    return r


def _motions_frame(motions: numpy.ndarray, programs: Sequence[str],
                   files: Sequence[str]):
    import pandas
    frame = pandas.DataFrame(motions)
    frame["motion"] = pandas.Categorical.from_codes(motions["motion"],
                                                    MOTION_NAMES)
    frame["prog"] = pandas.Categorical.from_codes(motions["prog"], programs)
    frame["file"] = pandas.Categorical.from_codes(motions["file"], files)
    return frame


def concatenate(motions: Sequence[Union[numpy.ndarray, "Result"]]) -> numpy.ndarray:
    """The motions of many runs on one machine as one array, in order.

    The rows of one Machine's runs number programs and files alike (the
    last run's `programs` and `files` name them all), so their arrays join
    as they are. One copy of the rows; numpy.concatenate would compare
    the structured dtypes field by field, which costs more than a short
    run."""
    arrays = [m.motions if isinstance(m, Result) else m for m in motions]
    return _mbc.concatenate(arrays)


def _profile_text(profile) -> Optional[str]:
    """A machine profile as JSON text: None, a path, a dict or a Machine."""
    if profile is None:
        return None
    if isinstance(profile, Machine):
        return profile.profile
    if isinstance(profile, Mapping):
        return json.dumps(profile)
    if not isinstance(profile, (str, os.PathLike)):
        raise TypeError("machine: a profile is None, a path, a dict or a "
                        f"Machine, not {type(profile).__name__}")
    with open(os.fspath(profile), encoding="utf-8") as f:
        return f.read()


class Machine:
    """A machine (a control and its machine profile) that keeps its state
    between runs: position, modal codes, offsets, common variables.

    profile: None (the built-in 3-axis metric mill), the path of a machine
    profile (docs/machine-profile.md) or the profile as a dict.  A run
    starts where the last left the machine, as a control starts a program
    after RESET; reset_state() puts the machine back to power-on, reset() to
    how it was made.  machine[100] reads a variable (None when vacant),
    machine[100] = 2.5 sets one (None makes it vacant).  One thread at a
    time (runs release the GIL; use one Machine per thread)."""

    def __init__(self, profile: Union[None, Source, Mapping[str, Any]] = None,
                 *, on_motion=None, on_print=None, on_alarm=None):
        self.profile = _profile_text(profile)
        self._ctx = _mbc.Context(self.profile)
        #: Called as a run goes, like the C API's sinks: on_motion(dict of
        #: the motion's fields, as a row of Result.motions with motion,
        #: prog and file by name), on_print(DPRNT text), on_alarm(report).
        #: An exception one raises stops the run before its next block and
        #: the call raises it.
        self.on_motion = on_motion
        self.on_print = on_print
        self.on_alarm = on_alarm

    @property
    def axes(self) -> str:
        """The axis letters in profile order, e.g. "XYZ"."""
        return self._ctx.axes

    @property
    def position(self) -> dict:
        """Where the tool stands, {"X": ...} in machine coordinates and the
        machine's unit (a lathe's X a diameter): what #5021+ read."""
        return {axis: self._ctx.get_position(i)
                for i, axis in enumerate(self.axes)}

    @position.setter
    def position(self, where: Mapping[str, float]) -> None:
        """Puts the tool elsewhere between runs, as jogging does: the axes
        given ({"Z": 50}); the next run starts there."""
        axes = self.axes
        for name, value in where.items():
            axis = axes.find(name.upper()) if isinstance(name, str) else -1
            if axis < 0:
                raise ValueError(f"position {name!r}: the machine's axes are "
                                 f"{', '.join(axes)}")
            self._ctx.set_position(axis, number_value(value,
                                                      f"position {name}"))

    def __getitem__(self, number: float) -> Optional[float]:
        return self._ctx.read(number)

    def __setitem__(self, number: float, value: Optional[float]) -> None:
        self._ctx.write(number, value)

    def reset(self) -> None:
        """Back to how the Machine was made (profile data and power-on)."""
        self._ctx.reset()

    def reset_state(self) -> None:
        """Power-on modal codes, the tool at the machine origin; variables
        and offsets stay."""
        self._ctx.reset_state()

    def run(self, program: "Program", args: Optional[Mapping[str, float]] = None,
            /, *, presets: Optional[Mapping[int, float]] = None,
            max_blocks: int = 0, **letters: float) -> Result:
        """Runs the program's main program on this machine with G65-style
        arguments (X=1.5 sets #24) and variable presets ({500: 1}); raises
        Alarm when an alarm stops the run."""
        if args:
            letters = {**args, **letters}
        result = Result._from(self._ctx.run(
            program._compiled, *_arguments(letters),
            _presets(presets) if presets else [], max_blocks,
            self.on_motion, self.on_print, self.on_alarm, MOTION_NAMES))
        alarm = result.alarm
        if alarm is not None and alarm.file == "" and alarm.line == 0:
            # Before any block: what the caller asked for (a preset of a
            # read-only variable), no alarm of the program's.
            raise ValueError(alarm.report.split("\n", 1)[0])
        if alarm is not None:
            raise alarm
        return result


# What the caller gives is checked before anything runs, the same way for
# keyword arguments, presets and batch tables: a wrong type is TypeError,
# a wrong value ValueError; mbc.Alarm is only ever the program's (docs/
# python.md, "Errors").


def argument_letter(name: str, what: str = "argument") -> str:
    """The G65 argument letter `name` names, in upper case (x passes X, as
    the control reads lower-case letters; the C API does the same)."""
    if not isinstance(name, str):
        raise TypeError(f"{what} {name!r}: a G65 argument is a letter")
    letter = name.upper()
    if len(letter) != 1 or not "A" <= letter <= "Z":
        raise ValueError(f"{what} {name!r}: a G65 argument is one letter")
    if letter in "GLNOP":
        raise ValueError(f"{what} {name}: G, L, N, O and P are not G65 "
                         "arguments")
    return letter


def number_value(value, what: str) -> float:
    """A value the caller gives: a real number (int, float, numpy's)."""
    if isinstance(value, (str, bytes)) or not isinstance(
            value, (int, float, numpy.number)):
        raise TypeError(f"{what}: a value is a number, not "
                        f"{type(value).__name__} {value!r}")
    return float(value)


def _arguments(args: Mapping[str, float]) -> tuple:
    """G65 arguments as the extension takes them: the letters and values."""
    letters, values = [], []
    for name, value in args.items():
        letter = argument_letter(name)
        if value is None:
            continue
        letters.append(letter)
        values.append(number_value(value, f"argument {name}"))
    return "".join(letters), values


def _presets(presets: Optional[Mapping[int, float]]) -> list:
    return [(number_value(n, "preset variable number"),
             number_value(v, f"preset #{n}"))
            for n, v in (presets or {}).items() if v is not None]


class Program:
    """Compiled programs (mbc.compile): call it to run its main program,
    `program(machine, X=..., Q=...)`; without a machine each call runs on a
    new Machine of the program's profile. Picklable: a copy compiles again
    (or loads the compiled-code cache) where it is unpickled."""

    def __init__(self, sources, main, opt, machine, strict, cache,
                 include_dirs):
        self._args = (sources, main, opt, machine, strict, cache, include_dirs)
        texts, files = [], []
        for source in sources:
            if isinstance(source, tuple):
                texts.append(source)
            else:
                files.append(source)
        self.machine_profile = _profile_text(machine)
        compiled, diagnostics, message = _mbc.compile(
            texts, files, main or "", opt, cache, strict,
            machine is None, list(include_dirs))
        self.diagnostics = tuple(Diagnostic._from(d) for d in diagnostics)
        if compiled is None:
            raise CompileError(message, self.diagnostics)
        self._compiled = compiled

    @property
    def main(self) -> str:
        """The main program's name, e.g. "O9200"."""
        return self._compiled.main

    @property
    def programs(self) -> list:
        """Every program of the input: (name, number)."""
        return self._compiled.programs

    def __call__(self, machine: Optional[Machine] = None, /, *,
                 presets: Optional[Mapping[int, float]] = None,
                 max_blocks: int = 0, **args: float) -> Result:
        if machine is None:
            machine = Machine(None) if self.machine_profile is None else \
                Machine(json.loads(self.machine_profile))
        return machine.run(self, args, presets=presets, max_blocks=max_blocks)

    def __reduce__(self):
        return (_cached_program, self._args)

    def __repr__(self) -> str:
        return f"<mbc.Program {self.main}>"


_programs: dict = {}


def _cached_program(sources, main, opt, machine, strict, cache, include_dirs):
    """One compile per process for the same input (a Dask worker gets many
    partitions of one batch)."""
    key = repr((sources, main, opt, machine, strict, cache, include_dirs))
    program = _programs.get(key)
    if program is None:
        program = _programs[key] = Program(sources, main, opt, machine, strict,
                                           cache, include_dirs)
    return program


def compile(sources: Union[Source, Sequence[Source]], main: Optional[str] = None,
            opt: int = 2, machine: Union[None, Source, Mapping[str, Any]] = None,
            *, strict: bool = True, cache: bool = True,
            include_dirs: Sequence[Source] = ()) -> Program:
    """Compiles Macro B programs for this machine's CPU (in process, through
    the compiled-code cache).

    sources: a path, source text (anything with a line break), or a list of
    them; programs they call are looked for beside the files and in
    include_dirs, as `mbc run -I` does.  main: the program to run ("O9200";
    default the first).  opt: 0-3, as -O0..-O3.  machine: the profile the
    programs are checked against and run on by default.  strict: errors in
    the source raise CompileError (False: as `mbc run`, each block that has
    one raises its alarm when it runs)."""
    if isinstance(sources, (str, os.PathLike)):
        sources = [sources]
    inputs = []
    for i, source in enumerate(sources):
        if isinstance(source, str) and ("\n" in source or "\r" in source):
            inputs.append((f"<source {i + 1}>" if len(sources) > 1 else "<source>",
                           source))
        else:
            inputs.append(os.fspath(source))
    if isinstance(machine, Machine):
        machine = json.loads(machine.profile) if machine.profile else None
    elif machine is not None and not isinstance(machine, Mapping):
        machine = os.fspath(machine)
    return Program(tuple(inputs), main, opt, machine, strict, cache,
                   tuple(os.fspath(d) for d in include_dirs))


from .batch import BatchInterrupted, batch  # noqa: E402  (uses the above)

__all__ = ["Alarm", "BatchInterrupted", "CompileError", "Diagnostic", "Error",
           "FixIt", "Machine", "MOTION_NAMES", "Program", "Result", "batch",
           "compile", "concatenate"]

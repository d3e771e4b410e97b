"""The package's API as a user meets it: compiling paths and text, errors in
the source, alarms as exceptions, arguments, a machine that keeps its state."""
import pickle

import numpy
import pandas
import pytest

import mbc

CYCLE = """%
O9100(BORE PATTERN)
IF[#18EQ#0]THEN#3000=1(RADIUS R MISSING)
#100=0
G90G0X#24Y#25Z5.
G1Z-#26F#9
G2I-#18
#100=#100+1
G0Z5.
M99
%
"""

NESTED = """%
O1
G65P9110A0
M30
O9110
#1=10/#1
M99
%
"""


def test_compile_text_and_run_with_arguments():
    program = mbc.compile(CYCLE)
    assert program.main == "O9100"
    result = program(X=10, Y=5, Z=2, R=4, F=200)
    rows = result.motions
    assert rows.dtype.names[:7] == ("motion", "line", "prog", "file", "cycle",
                                    "plane", "f")
    assert [mbc.MOTION_NAMES[k] for k in rows["motion"]] == \
        ["rapid", "linear", "cw", "rapid"]
    arc = rows[2]
    assert (arc["x"], arc["y"], arc["cx"], arc["cy"]) == (10, 5, 6, 5)
    assert numpy.isnan(arc["cz"]) and numpy.isnan(rows[0]["f"])
    assert rows[1]["z"] == -2 and rows[1]["f"] == 200
    assert result.programs[arc["prog"]] == "O9100"
    assert result.files[arc["file"]] == "<source>"
    assert result.variables == {100: 1.0}
    assert result.blocks == 8 and result.moves == 4
    assert result.cycle_time > 0 and result.summary["moves"] == 4


def test_macro_alarm_is_an_exception_with_the_controls_number():
    program = mbc.compile(CYCLE)
    with pytest.raises(mbc.Alarm) as caught:
        program(X=1)
    alarm = caught.value
    assert (alarm.number, alarm.code, alarm.message) == \
        (3001, "3001", "RADIUS R MISSING")
    assert (alarm.file, alarm.line) == ("<source>", 3)
    assert alarm.call_stack == ()
    assert str(alarm) == "<source>:3: alarm 3001: RADIUS R MISSING"
    assert alarm.result.blocks == 1


def test_program_alarm_names_its_call_stack():
    with pytest.raises(mbc.Alarm) as caught:
        mbc.compile(NESTED)()
    alarm = caught.value
    assert (alarm.number, alarm.code, alarm.message) == \
        (112, "PS0112", "ZERO DIVIDE")
    assert alarm.line == 6
    assert alarm.call_stack == (("O9110", "<source>", 3),)
    assert "in O9110 called from <source>:3" in alarm.report


def test_errors_in_the_source_raise_compile_error_with_diagnostics():
    with pytest.raises(mbc.CompileError) as caught:
        mbc.compile("%\nO1\n#1=[2+3\nM30\n%\n")
    error = caught.value
    assert error.errors, error.diagnostics
    first = error.errors[0]
    assert (first.file, first.line) == ("<source>", 3)
    assert first.column > 0 and first.message
    assert "<source>:3:" in str(error)


def test_without_strict_a_bad_block_alarms_when_it_runs():
    program = mbc.compile("%\nO1\n#100=1\n#1=[2+3\nM30\n%\n", strict=False)
    assert any(d.severity == "error" for d in program.diagnostics)
    with pytest.raises(mbc.Alarm) as caught:
        program()
    assert caught.value.line == 4
    assert caught.value.result.variables == {100: 1.0}


def test_a_machine_keeps_position_modal_state_and_variables():
    step = mbc.compile("%\nO2\nG91G1X10.F100\n#500=#500+1\nM30\n%\n")
    machine = mbc.Machine()
    machine[500] = 0
    first = step(machine)
    second = step(machine)
    assert first.motions["sx"][0] == 0 and second.motions["sx"][0] == 10
    assert second.motions["x"][0] == 20
    assert machine[500] == 2 and machine[4003] == 91
    machine.reset_state()
    assert machine[5001] == 0 and machine[4003] == 90 and machine[500] == 2
    machine.reset()
    assert machine[500] is None
    # Without a machine every call starts from power-on.
    assert step().motions["x"][0] == 10 and step().motions["x"][0] == 10


def test_machine_profiles_from_a_dict():
    machine = mbc.Machine({"axes": ["X", "Y", "Z", "A"]})
    assert machine.axes == "XYZA"
    result = mbc.compile("%\nO3\nG0A90.\nM30\n%\n")(machine)
    assert result.motions["a"][0] == 90 and "ma" in result.motions.dtype.names
    with pytest.raises(ValueError):
        mbc.Machine({"axes": 5})


def test_presets_and_bad_arguments():
    program = mbc.compile("%\nO4\n#101=#100*2\nM30\n%\n")
    assert program(presets={100: 4}).variables == {100: 4.0, 101: 8.0}
    with pytest.raises(ValueError, match="one letter"):
        program(XY=1)


# The caller's mistakes are ValueError or TypeError before anything runs;
# mbc.Alarm is the program's alone.
def test_callers_errors_are_value_and_type_errors():
    program = mbc.compile("%\nO5\n#100=#24\n#101=#7\nM30\n%\n")
    machine = mbc.Machine()
    # x is X, as the control and the C API read a lower-case letter.
    assert program(machine, x=1.5, d=numpy.float32(2)).variables == \
        {100: 1.5, 101: 2.0}
    with pytest.raises(ValueError, match="G, L, N, O and P"):
        program(machine, P=5)
    with pytest.raises(TypeError, match="a value is a number, not str"):
        program(machine, D="16")
    with pytest.raises(TypeError, match="a G65 argument is a letter"):
        machine.run(program, {24: 1.0})
    with pytest.raises(ValueError, match="PS0116: WRITE PROTECTED"):
        program(machine, presets={5001: 1.0})
    with pytest.raises(TypeError):
        program(machine, presets={"#100": 1.0})
    with pytest.raises(TypeError, match="machine: a profile is"):
        mbc.Machine(5)
    with pytest.raises(TypeError, match="machine: a profile is"):
        mbc.batch(program, pandas.DataFrame({"X": [1.0]}), machine=5)
    for column, error in (("p", ValueError), ("#5001", ValueError),
                          ("#100000", ValueError)):
        with pytest.raises(error, match=f"column {column}"):
            mbc.batch(program, pandas.DataFrame({column: [1.0]}))
    with pytest.raises(TypeError, match="column X"):
        mbc.batch(program, pandas.DataFrame({"X": ["16"]}))
    # The program's own alarm stays an Alarm.
    with pytest.raises(mbc.Alarm):
        mbc.compile("%\nO6\n#3000=1(STOP)\nM30\n%\n")(machine)


def test_a_program_pickles_as_its_source():
    program = mbc.compile(CYCLE)
    copy = pickle.loads(pickle.dumps(program))
    assert copy.main == "O9100"
    assert copy(X=0, Y=0, Z=1, R=2, F=100).variables == {100: 1.0}


def test_motions_of_many_runs_concatenate():
    program = mbc.compile(CYCLE)
    machine = mbc.Machine()
    runs = [program(machine, X=i, Y=0, Z=1, R=2, F=100) for i in range(3)]
    joined = mbc.concatenate(runs)
    assert len(joined) == sum(len(r.motions) for r in runs)
    assert joined.dtype == runs[0].motions.dtype
    assert list(joined["x"][4:8]) == list(runs[1].motions["x"])
    assert {runs[-1].programs[i] for i in joined["prog"]} == {"O9100"}
    other = mbc.compile("%\nO5\nG0A1.\nM30\n%\n")(mbc.Machine(
        {"axes": ["X", "Y", "Z", "A"]}))
    with pytest.raises(ValueError):
        mbc.concatenate([runs[0], other])


def test_a_machine_is_one_threads_at_a_time():
    import threading
    endless = mbc.compile("%\nO6\nWHILE[1EQ1]DO1\n#100=#100+1\nEND1\n%\n")
    machine = mbc.Machine()
    started = threading.Event()
    outcome = []

    def run():
        started.set()
        try:
            endless(machine)  # to the default limit: a second or so
        except mbc.Alarm as alarm:
            outcome.append(alarm.code)

    worker = threading.Thread(target=run)
    worker.start()
    started.wait()
    refused = 0
    while worker.is_alive():
        try:
            machine[100]
        except RuntimeError as error:
            assert "another thread" in str(error)
            refused += 1
    worker.join()
    assert outcome == ["MBC0002"]
    assert refused > 0
    assert machine[100] is not None


def test_ctrl_c_stops_a_runaway_run_with_keyboard_interrupt():
    import os
    import signal
    import threading
    import time
    endless = mbc.compile("%\nO7\nWHILE[1EQ1]DO1\n#100=#100+1\nEND1\n%\n")
    machine = mbc.Machine()
    # The signal comes while the main thread is in the run.
    timer = threading.Timer(0.2, os.kill, (os.getpid(), signal.SIGINT))
    timer.start()
    began = time.perf_counter()
    with pytest.raises(KeyboardInterrupt):
        endless(machine, max_blocks=10**15)
    assert time.perf_counter() - began < 30
    assert machine[100] > 0  # the machine is still there, and usable
    assert mbc.compile("%\nO8\n#101=1\nM30\n%\n")(machine).variables[101] == 1


# A simulation puts the tool where its own model left it before a call.
def test_the_machine_position_between_runs():
    machine = mbc.Machine()
    assert machine.position == {"X": 0.0, "Y": 0.0, "Z": 0.0}
    machine.position = {"x": -50, "Z": 10.5}
    assert machine.position == {"X": -50.0, "Y": 0.0, "Z": 10.5}
    assert machine[5021] == -50.0
    step = mbc.compile("%\nO9\nG91G01X5.F100.\nM30\n%\n")
    moves = step(machine).motions
    assert (moves["sx"][0], moves["x"][0]) == (-50.0, -45.0)
    assert machine.position["X"] == -45.0
    with pytest.raises(ValueError, match="axes are X, Y, Z"):
        machine.position = {"A": 1.0}
    with pytest.raises(ValueError, match="nine digits"):
        machine.position = {"X": 1e12}
    with pytest.raises(TypeError):
        machine.position = {"X": "1"}


# A Machine's callbacks see the run as it goes, as the C API's sinks do.
def test_machine_callbacks_as_the_run_goes():
    seen, printed, alarms = [], [], []
    machine = mbc.Machine(on_motion=seen.append, on_print=printed.append,
                          on_alarm=alarms.append)
    program = mbc.compile("%\nO11(STEPS)\nG90G00X1.Y2.\nG01X#24F100.\n"
                          "DPRNT[AT*#5041[42]]\n#3000=5(STOP)\nM30\n%\n")
    with pytest.raises(mbc.Alarm) as stopped:
        program(machine, X=5)
    rows = stopped.value.result.motions
    assert [s["motion"] for s in seen] == ["rapid", "linear"]
    assert [s["x"] for s in seen] == list(rows["x"])
    assert seen[1]["prog"] == "O0011" and seen[1]["line"] == 4
    assert seen[1]["f"] == 100.0
    assert printed == ["AT     5.00\n"]
    assert alarms == [stopped.value.report]

    # An exception in a callback stops the run before its next block.
    def refuse(motion):
        raise ValueError(f"collision at X{motion['x']}")
    careful = mbc.Machine(on_motion=refuse)
    with pytest.raises(ValueError, match="collision at X1.0"):
        program(careful, X=5)
    assert careful.position["X"] == 1.0
    careful.on_motion = None  # the machine runs on
    with pytest.raises(mbc.Alarm):
        program(careful, X=5)
    assert careful.position["X"] == 5.0

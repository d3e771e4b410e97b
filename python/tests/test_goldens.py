"""The golden programs of tests/programs run from Python give what `mbc run`
gives (its expected files): the toolpath records rebuilt from the motions
array byte for byte, DPRNT, the variables, the alarm report, the counts."""
import json

import pytest

import mbc
from conftest import SOURCE, toolpath_jsonl

PROGRAMS = SOURCE / "tests" / "programs"


def plain_cases():
    """The cases `mbc run` runs without options on the default machine."""
    for nc in sorted(PROGRAMS.glob("*.nc")):
        stem = nc.with_suffix("")
        if not any(stem.with_suffix(s).exists() for s in (".args", ".check")):
            yield nc.stem


@pytest.mark.parametrize("name", list(plain_cases()))
def test_golden(name, monkeypatch):
    monkeypatch.chdir(PROGRAMS)
    expected = lambda suffix: (PROGRAMS / (name + suffix))
    # strict=False: errors make their blocks alarm, as under `mbc run`.
    program = mbc.compile(name + ".nc", strict=False)
    machine = mbc.Machine()
    try:
        result = program(machine)
        alarm = None
    except mbc.Alarm as stopped:
        alarm, result = stopped, stopped.result
    if expected(".toolpath.jsonl").exists():
        assert toolpath_jsonl(result, "xyz") == \
            expected(".toolpath.jsonl").read_text()
    if expected(".dprnt").exists():
        assert result.dprnt == expected(".dprnt").read_text()
    if expected(".vars.json").exists():
        want = json.loads(expected(".vars.json").read_text())
        assert {str(k): v for k, v in result.variables.items()} == want
    if not expected(".stderr").exists():
        return
    stderr = expected(".stderr").read_text()
    if alarm is not None:
        assert alarm.report in stderr
        assert f"{alarm.file}:{alarm.line}: alarm {alarm.code}" in stderr
    summary = (f"mbc: {result.main}: {result.blocks} blocks, {result.moves} "
               f"moves, {0 if alarm is None else 1} alarm")
    assert summary in stderr
    if result.messages:
        assert result.messages in stderr

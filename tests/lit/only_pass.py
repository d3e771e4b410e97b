"""%only-NAME of the lit tests: the --disable-pass options that leave only
pass NAME on. lit.cfg.py makes the substitutions from it, and
tools/update_lit_checks.py expands RUN lines with it. The names come from
ir/passes/passes.def."""

import pathlib
import re

PASSES_DEF = pathlib.Path(__file__).resolve().parents[2] / "ir" / "passes" / "passes.def"


def pass_names():
    return re.findall(r'^PASS\(\w+, "([a-z0-9-]+)"', PASSES_DEF.read_text(),
                      re.M)


def only_pass(name, names):
    """The options, as a list of words, that turn off every pass but name."""
    words = []
    for other in names:
        if other != name:
            words += ["--disable-pass", other]
    return words

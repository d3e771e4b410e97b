# lit configuration for mbc's FileCheck tests (IR lowering and passes, and
# the limits of tests/lit/robustness).
# The build writes lit.site.cfg.py with the paths; ctest runs lit on it.
import os
import re
import sys

import lit.formats

config.name = "mbc"
config.test_format = lit.formats.ShTest(execute_external=False)
config.suffixes = [".nc", ".mbir", ".test"]
config.test_source_root = os.path.dirname(__file__)
config.substitutions.append(("%mbc", config.mbc_path))
# Robustness tests generate their (large) inputs.
config.substitutions.append(("%python", sys.executable))

# %only-NAME: the --disable-pass options that leave only pass NAME on, for
# tests of one pass. The names come from ir/passes/passes.def.
with open(os.path.join(config.test_source_root, "..", "..", "ir", "passes",
                       "passes.def")) as f:
    passes = re.findall(r'^PASS\(\w+, "([a-z0-9-]+)"', f.read(), re.M)
for name in passes:
    others = " ".join("--disable-pass " + p for p in passes if p != name)
    config.substitutions.append(("%only-" + name, others))
config.environment["PATH"] = os.pathsep.join(
    [config.llvm_tools_dir, config.environment.get("PATH", "")])

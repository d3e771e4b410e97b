# lit configuration for mbc's FileCheck tests (IR lowering and passes, and
# the limits of tests/lit/robustness).
# The build writes lit.site.cfg.py with the paths; ctest runs lit on it.
import os
import sys

import lit.formats

config.name = "mbc"
config.test_format = lit.formats.ShTest(execute_external=False)
config.suffixes = [".nc", ".mbir", ".test"]
config.test_source_root = os.path.dirname(__file__)
config.substitutions.append(("%mbc", config.mbc_path))
# LLVM's own code generator on the IR mbc emits, which is written with
# opaque pointers: the llc of llvm_tools_dir (LLVM 14) reads them only when
# told.
config.substitutions.append(("%llc", "llc -opaque-pointers"))
# Robustness tests generate their (large) inputs.
config.substitutions.append(("%python", sys.executable))

# %only-NAME: the --disable-pass options that leave only pass NAME on, for
# tests of one pass (only_pass.py).
sys.dont_write_bytecode = True  # nothing written into the source tree
sys.path.insert(0, config.test_source_root)
from only_pass import only_pass, pass_names  # noqa: E402

passes = pass_names()
for name in passes:
    config.substitutions.append(
        ("%only-" + name, " ".join(only_pass(name, passes))))
config.environment["PATH"] = os.pathsep.join(
    [config.llvm_tools_dir, config.environment.get("PATH", "")])
# The suite's cache of compiled code (tests/CMakeLists.txt), not the user's.
if "MBC_CACHE_DIR" in os.environ:
    config.environment["MBC_CACHE_DIR"] = os.environ["MBC_CACHE_DIR"]

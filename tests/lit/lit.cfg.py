# lit configuration for mbc's FileCheck tests (IR lowering and passes).
# The build writes lit.site.cfg.py with the paths; ctest runs lit on it.
import lit.formats

config.name = "mbc"
config.test_format = lit.formats.ShTest(execute_external=False)
config.suffixes = [".nc", ".mbir"]
config.test_source_root = os.path.dirname(__file__)
config.substitutions.append(("%mbc", config.mbc_path))
config.environment["PATH"] = os.pathsep.join(
    [config.llvm_tools_dir, config.environment.get("PATH", "")])

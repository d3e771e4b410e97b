// An executable made by `mbc build`: the run options of `mbc run` (without
// input files), the program table compiled into it, one run.
#include "driver/aot_main.h"

#include "driver/run_session.h"
#include <mbc/engine.h>

#include <cstdio>

using namespace mbc::driver;

namespace {

int usage(const char* self, const std::string& error) {
  std::FILE* out = error.empty() ? stdout : stderr;
  if (!error.empty()) {
    std::fprintf(out, "%s: error: %s\n", self, error.c_str());
  }
  std::fprintf(out, "usage: %s\n%s", self, runOptionsUsage(8).c_str());
  return error.empty() ? 0 : 2;
}

} // namespace

extern "C" int mbc_aot_main(int argc, char** argv,
                            const mbrt_program_table* table) {
  const char* self = argc > 0 ? argv[0] : "mbc-program";
  RunOptions o;
  ArgReader args(argc, argv, 1);
  std::string error;
  while (args.advance()) {
    if (args.name() == "--help" || args.name() == "-h") {
      return usage(self, "");
    }
    OptionStatus s = readRunOption(args, o, error);
    if (s == OptionStatus::NotARunOption) {
      error = args.arg().starts_with("-")
                  ? "unknown option '" + args.arg() + "'"
                  : "unexpected argument '" + args.arg() +
                        "' (the programs are compiled in)";
    }
    if (s != OptionStatus::Taken) {
      return usage(self, error);
    }
  }
  const mbrt_program* main =
      o.mainProgram.empty()
          ? (table->count > 0 ? &table->programs[0] : nullptr)
          : mbrt_find_program(table, -1, o.mainProgram.c_str());
  if (main == nullptr) {
    std::fprintf(stderr, "%s: error: no program %s in this executable\n", self,
                 o.mainProgram.c_str());
    return 2;
  }
  return runOnce(o, main->name, [main, table](mbrt_ctx* ctx) {
    mbrt_name_programs(ctx, table);
    return mbrt_run_body(ctx, main);
  });
}

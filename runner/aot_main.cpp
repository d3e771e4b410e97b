// An executable made by `mbc build`: the run options of `mbc run` (without
// input files), the program table compiled into it, one run.
#include "runner/aot_main.h"

#include <mbc/engine.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <iostream>

#include "runner/help_formatter.h"
#include "runner/run_session.h"

using namespace mbc::runner;

extern "C" int mbc_aot_main(int argc, char** argv,
                            const mbrt_program_table* table) {
  const char* self = argc > 0 ? argv[0] : "mbc-program";
  RunOptions o;
  std::string error;
  CLI::App app("Runs the Macro B programs compiled into this executable "
               "(made by mbc build).",
               self);
  useHelpFormatter(app);
  app.set_help_flag("-h,--help", "print this help and exit");
  addRunOptions(app, o, error, RunOutputs::Single);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    std::cout << app.help();
    return 0;
  } catch (const CLI::ParseError& e) {
    error = e.what();
  }
  if (error.empty()) {
    error = runOptionsProblem(o);
  }
  if (!error.empty()) {
    std::fprintf(stderr, "%s: error: %s\n", self, error.c_str());
    std::fprintf(stderr, "%s: note: '%s --help' lists the options\n", self,
                 self);
    return 2;
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

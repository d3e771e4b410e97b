// An allocation that fails must end mbc with "out of memory": never a
// crash, and never a wrong result. While LLVM compiles, which is not
// exception-safe, mbc exits with status 4; elsewhere std::bad_alloc reaches
// main, which says the same. This executable replaces operator new with one
// that fails the n-th allocation from a point on, as malloc would under a
// memory limit (calling the new-handler, then throwing), and fails each of
// a spread of the allocations of an object file's compile and of a whole
// `mbc run`, in a child process of its own.
#include "codegen/object_file.h"
#include "driver/emit_ir_command.h"
#include "driver/run_command.h"
#include <mbc/read_file.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <new>
#include <stdlib.h>
#include <string>
#include <sys/wait.h>
#include <vector>

namespace {

// Allocations left before the one that fails; negative: none fails.
std::atomic<long> gAllocationsLeft{-1};
std::atomic<long> gAllocations{0};

void* allocate(std::size_t size) {
  gAllocations.fetch_add(1, std::memory_order_relaxed);
  for (;;) {
    const bool fail =
        gAllocationsLeft.load(std::memory_order_relaxed) >= 0 &&
        gAllocationsLeft.fetch_sub(1, std::memory_order_relaxed) == 0;
    if (void* p = fail ? nullptr : std::malloc(size == 0 ? 1 : size)) {
      return p;
    }
    std::new_handler handler = std::get_new_handler();
    if (handler == nullptr) {
      throw std::bad_alloc();
    }
    handler();
  }
}

} // namespace

void* operator new(std::size_t size) {
  return allocate(size);
}

void* operator new[](std::size_t size) {
  return allocate(size);
}

void operator delete(void* p) noexcept {
  std::free(p);
}

void operator delete[](void* p) noexcept {
  std::free(p);
}

void operator delete(void* p, std::size_t) noexcept {
  std::free(p);
}

void operator delete[](void* p, std::size_t) noexcept {
  std::free(p);
}

namespace {

using namespace mbc;

// Loops, a macro call, a computed jump and DPRNT: enough for the passes and
// the code generator to allocate at every stage.
constexpr const char* kProgram = R"(%
O1000
#1 = 0
WHILE [#1 LT 10] DO1
G01 X[#1 * 2] Y[SIN[#1 * 36]] F500
G65 P2000 A#1
#1 = #1 + 1
END1
#2 = 20
GOTO #2
N10 #3 = 1
N20 DPRNT[X#1[43]]
M30
O2000
#100 = #100 + #1
IF [#1 GT 5] GOTO 5
#101 = ROUND[#1 / 3]
N5 M99
%
)";

ir::Module loadProgram(const std::filesystem::path& dir) {
  const std::filesystem::path source = dir / "oom.nc";
  std::ofstream(source) << kProgram;
  driver::Options o;
  o.command = "run";
  o.files = {source.string()};
  ir::Module m;
  EXPECT_TRUE(driver::loadModule(o, m));
  return m;
}

// Counts the allocations of `work` (the second time: the first also makes
// LLVM's one-time state), then, each in a child process that runs `child`
// (`work` and what follows), fails one of `samples` of them spread over the
// whole of it (every one when there are fewer): every child must end with
// the message and a status `ended` accepts.
template <class Work, class Child, class Ended>
void failEachSample(Work work, Child child, int samples, Ended ended) {
  work();
  gAllocations = 0;
  work();
  const long total = gAllocations.load();
  const long tried = std::min<long>(total, samples);
  for (long i = 0; i < tried; ++i) {
    const long failing = total * i / tried;
    EXPECT_EXIT(
        {
          gAllocationsLeft = failing;
          child();
          // Said here, so that a count that does not hold shows as such.
          std::fputs(gAllocationsLeft.load() >= 0
                         ? "the failing allocation never came\n"
                         : "the failed allocation was absorbed\n",
                     stderr);
          std::exit(0);
        },
        ended, "(out of memory|OUT OF MEMORY|outputs are complete)")
        << "failing allocation " << failing << " of " << total;
  }
}

// A compile that fails for another reason says so on stderr, where a
// child's message is matched (gtest prints its failures on stdout).
void expectCompiled(bool compiled, const std::string& error) {
  if (!compiled) {
    std::fprintf(stderr, "the compile failed: %s\n", error.c_str());
    ADD_FAILURE() << error;
  }
}

class OutOfMemory : public ::testing::Test {
protected:
  // A folder of this process's own: ctest runs these tests in parallel,
  // and two that started in the same millisecond once shared one named
  // after gtest's time-based seed, each removing it under the other.
  void SetUp() override {
    std::string pattern =
        (std::filesystem::temp_directory_path() / "mbc_oom_XXXXXX").string();
    ASSERT_NE(mkdtemp(pattern.data()), nullptr);
    dir_ = pattern;
    module_ = loadProgram(dir_);
  }

  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::filesystem::path dir_;
  ir::Module module_;
};

TEST_F(OutOfMemory, ObjectFileCompileExits) {
  const std::string path = (dir_ / "oom.o").string();
  for (int level : {0, 2}) {
    codegen::ObjectOptions options;
    options.optLevel = level;
    const auto compile = [&] {
      std::string error;
      expectCompiled(codegen::writeCompiled(module_, options,
                                            codegen::FileKind::Object, path,
                                            error),
                     error);
    };
    failEachSample(compile, compile, 40, ::testing::ExitedWithCode(4));
  }
}

// The whole of `mbc run` under the interpreter: reading the program, the
// front end, the runtime and the run. Reading through a stream once took a
// failed allocation for the end of the file, and the program, cut short,
// got syntax errors.
// The file's bytes; empty when there is none.
std::string contents(const std::string& path) {
  std::string text;
  readFile(path, text);
  return text;
}

// True when `path` is empty or ends with a whole line.
bool endsWithWholeLine(const std::string& path) {
  const std::string text = contents(path);
  return text.empty() || text.back() == '\n';
}

// Runs as `mbc run` does (a std::bad_alloc that reaches main ends it with
// status 4 and the message). A run that ended with an alarm must have
// flushed whole records; one that ended well (a failure that the
// reserve absorbed outside a run) must have written what `reference` holds
// (toolpath, DPRNT, variables). The child's status is what mbc's would be.
void runAsMbc(const driver::Options& o,
              const std::vector<std::string>& reference) {
  try {
    const int status = driver::runCommand(o);
    if (status == 0) {
      if (reference != std::vector<std::string>{contents(o.run.toolpathPath),
                                                contents(o.run.dprntPath),
                                                contents(o.run.varsOutPath)}) {
        std::fputs("the outputs differ from a run with memory enough\n",
                   stderr);
        std::exit(98);
      }
      std::fputs("the outputs are complete\n", stderr);
      std::exit(0);
    }
    {
      if (!endsWithWholeLine(o.run.toolpathPath) ||
          !endsWithWholeLine(o.run.dprntPath)) {
        std::fputs("an output ends in the middle of a record\n", stderr);
        std::exit(99);
      }
      std::exit(status);
    }
  } catch (const std::bad_alloc&) {
    std::fputs("mbc: error: out of memory\n", stderr);
    std::exit(4);
  }
}

std::vector<std::string> outputsOf(const driver::Options& o) {
  EXPECT_EQ(driver::runCommand(o), 0);
  return {contents(o.run.toolpathPath), contents(o.run.dprntPath),
          contents(o.run.varsOutPath)};
}

driver::Options runOptions(const std::filesystem::path& dir,
                           const std::string& program,
                           toolchain::Engine engine) {
  driver::Options o;
  o.command = "run";
  o.files = {(dir / program).string()};
  o.engine = engine;
  // Every run generates its code: a cached one would skip LLVM.
  o.noCache = true;
  o.run.toolpathPath = (dir / "toolpath.jsonl").string();
  o.run.dprntPath = (dir / "dprnt.txt").string();
  o.run.varsOutPath = (dir / "vars.json").string();
  return o;
}

// 0: the outputs are complete; 2: the runtime could not be created (a
// usage error's status); 3: the run stopped with alarm MBC0005; 4: out of
// memory before or after the run.
bool endedForLackOfMemory(int status) {
  return WIFEXITED(status) && WEXITSTATUS(status) != 1 &&
         WEXITSTATUS(status) <= 4;
}

// The whole of `mbc run` under the interpreter: reading the program, the
// front end, the runtime and the run. Reading through a stream once took a
// failed allocation for the end of the file, and the program, cut short,
// got syntax errors.
TEST_F(OutOfMemory, InterpreterRunSaysOutOfMemory) {
  const driver::Options o =
      runOptions(dir_, "oom.nc", toolchain::Engine::Interp);
  const std::vector<std::string> reference = outputsOf(o);
  failEachSample([&] { driver::runCommand(o); },
                 [&] { runAsMbc(o, reference); }, 1000, endedForLackOfMemory);
}

// A run of compiled code: a std::bad_alloc cannot unwind through it (the
// process aborted), so the run stops before its next block with MBC0005
// and its outputs end with whole records.
TEST_F(OutOfMemory, CompiledRunStopsWithAnAlarm) {
  std::ofstream(dir_ / "long.nc") << R"(%
O1000
#1 = 0
WHILE [#1 LT 400] DO1
G01 X[#1 / 10] Y[SIN[#1]] F500
DPRNT[I#1[40]*X#5001[43]]
#1 = #1 + 1
END1
M30
%
)";
  const driver::Options o = runOptions(dir_, "long.nc", toolchain::Engine::Jit);
  const std::vector<std::string> reference = outputsOf(o);
  failEachSample([&] { driver::runCommand(o); },
                 [&] { runAsMbc(o, reference); }, 80, endedForLackOfMemory);
}

} // namespace

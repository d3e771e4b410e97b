// Per-operation costs of the runtime every engine shares, timed in process
// with Google Benchmark: what one NC block, one variable access or one
// function costs, beside the whole-program timings of bench/run.py.
#include <mbc/arith.h>
#include <mbc/engine.h>
#include <mbc/toolpath_json.h>

#include <benchmark/benchmark.h>
#include <cstdint>
#include <initializer_list>
#include <string>

#include "motion.h"

namespace {

/// A running context with no sinks and no block limit.
class Context {
public:
  Context() {
    char err[256];
    ctx_ = mbrt_create(nullptr, err, sizeof err);
    mbrt_start(ctx_, "MAIN");
    mbrt_set_max_blocks(ctx_, UINT64_MAX);
  }

  ~Context() { mbrt_destroy(ctx_); }

  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  mbrt_ctx* get() { return ctx_; }

  /// One NC block the way compiled code sends it; false after an alarm.
  bool block(std::initializer_list<mbrt_word> words) {
    mbrt_flow flow;
    return mbrt_begin_block(ctx_, "micro", 1) == 0 &&
           mbrt_nc_block(ctx_, words.begin(), words.size(), &flow) == 0;
  }

private:
  mbrt_ctx* ctx_ = nullptr;
};

mbrt_word w(char letter, double value) {
  return {letter, MBRT_WORD_VALUE, value};
}

/// G01 moves to and fro along X at F1000.
void runLinearMoves(benchmark::State& state, Context& ctx) {
  if (!ctx.block({w('G', 1), w('F', 1000)})) {
    state.SkipWithError("alarm");
  }
  double x = 0.0;
  for (auto _ : state) {
    x = 10.0 - x;
    if (!ctx.block({w('G', 1), w('X', x)})) {
      state.SkipWithError("alarm");
      break;
    }
  }
  state.SetItemsProcessed(state.iterations());
}

void LinearMove(benchmark::State& state) {
  Context ctx;
  runLinearMoves(state, ctx);
}

BENCHMARK(LinearMove);

/// The motion of LinearMove's blocks alone, from their words in counts as
/// the block's decoding hands them on: the difference from LinearMove is
/// what reading a block costs (words, G codes, calls, statement start).
void LinearMotion(benchmark::State& state) {
  Context ctx;
  if (!ctx.block({w('G', 1), w('F', 1000)})) {
    state.SkipWithError("alarm");
  }
  mbrt_ctx& machine = *ctx.get();
  mbc::rt::MotionWords words;
  words.axisMask = 1; // X
  const auto far = static_cast<mbc::rt::Counts>(10.0 * machine.countsPerMm());
  for (auto _ : state) {
    words.axis[0] = far - words.axis[0];
    if (mbc::rt::executeMotion(machine, words) != 0) {
      state.SkipWithError("alarm");
      break;
    }
  }
  state.SetItemsProcessed(state.iterations());
}

BENCHMARK(LinearMotion);

/// The same moves handed to a motion sink: the cost of filling mbrt_motion.
void LinearMoveToSink(benchmark::State& state) {
  Context ctx;
  std::uint64_t seen = 0;
  mbrt_set_motion_sink(
      ctx.get(),
      [](void* user, const mbrt_motion* motion) {
        *static_cast<std::uint64_t*>(user) += motion->kind != 0;
      },
      &seen);
  runLinearMoves(state, ctx);
  benchmark::DoNotOptimize(seen);
}

BENCHMARK(LinearMoveToSink);

/// Text gathered the way the output files gather it, 64 KiB at a time.
void gather(std::string& text) {
  if (text.size() > 65536) {
    text.clear();
  }
}

/// The same moves as `--toolpath` JSONL records: the writer's cost is the
/// difference from LinearMoveToSink.
void LinearMoveToJsonl(benchmark::State& state) {
  Context ctx;
  std::string text;
  mbrt_set_motion_sink(
      ctx.get(),
      [](void* user, const mbrt_motion* motion) {
        auto& out = *static_cast<std::string*>(user);
        gather(out);
        mbc::appendToolpathJson(out, *motion);
      },
      &text);
  runLinearMoves(state, ctx);
  benchmark::DoNotOptimize(text.data());
}

BENCHMARK(LinearMoveToJsonl);

/// The same moves as `--gcode` blocks: the difference from LinearMove.
void LinearMoveToGcode(benchmark::State& state) {
  Context ctx;
  std::string text;
  mbrt_set_gcode_sink(
      ctx.get(),
      [](void* user, const char* data, size_t size) {
        auto& out = *static_cast<std::string*>(user);
        gather(out);
        out.append(data, size);
      },
      &text);
  runLinearMoves(state, ctx);
  benchmark::DoNotOptimize(text.data());
}

BENCHMARK(LinearMoveToGcode);

/// Half circles G02 X20 I10 and back with I-10.
void ArcMove(benchmark::State& state) {
  Context ctx;
  if (!ctx.block({w('G', 1), w('F', 1000)})) {
    state.SkipWithError("alarm");
  }
  double x = 0.0;
  for (auto _ : state) {
    const double center = x == 0.0 ? 10.0 : -10.0;
    x = 20.0 - x;
    if (!ctx.block({w('G', 2), w('X', x), w('I', center)})) {
      state.SkipWithError("alarm");
      break;
    }
  }
  state.SetItemsProcessed(state.iterations());
}

BENCHMARK(ArcMove);

/// A block without motion: the fixed cost of every NC block.
void FeedOnlyBlock(benchmark::State& state) {
  Context ctx;
  for (auto _ : state) {
    if (!ctx.block({w('F', 500)})) {
      state.SkipWithError("alarm");
      break;
    }
  }
}

BENCHMARK(FeedOnlyBlock);

/// What every macro statement pays: position, line and the block limit.
void BeginBlock(benchmark::State& state) {
  Context ctx;
  for (auto _ : state) {
    benchmark::DoNotOptimize(mbrt_begin_block(ctx.get(), "micro", 1));
  }
}

BENCHMARK(BeginBlock);

/// #[#1] on a common variable: what indirection costs compiled code.
void ReadCommon(benchmark::State& state) {
  Context ctx;
  mbrt_write_var(ctx.get(), 100.0, 1.5, nullptr);
  mbrt_num value = 0.0;
  for (auto _ : state) {
    mbrt_read_var(ctx.get(), 100.0, &value);
    benchmark::DoNotOptimize(value);
  }
}

BENCHMARK(ReadCommon);

void WriteCommon(benchmark::State& state) {
  Context ctx;
  double value = 0.0;
  for (auto _ : state) {
    value += 1.0;
    benchmark::DoNotOptimize(mbrt_write_var(ctx.get(), 100.0, value, nullptr));
  }
}

BENCHMARK(WriteCommon);

/// One function of the language on arguments that change every call, within
/// two turns as angles in macros mostly are.
void Function(benchmark::State& state, mbc::Builtin f) {
  const mbc::MathParams params;
  double args[2] = {0.0, 7.0};
  mbc::Num out = 0.0;
  for (auto _ : state) {
    args[0] = args[0] > 720.0 ? 0.3 : args[0] + 1.25;
    mbc::evalBuiltin(f, args, params, &out);
    benchmark::DoNotOptimize(out);
  }
}

BENCHMARK_CAPTURE(Function, SIN, mbc::Builtin::Sin);
BENCHMARK_CAPTURE(Function, ATAN2, mbc::Builtin::Atan2);
BENCHMARK_CAPTURE(Function, SQRT, mbc::Builtin::Sqrt);
BENCHMARK_CAPTURE(Function, ROUND, mbc::Builtin::Round);

} // namespace

BENCHMARK_MAIN();

// A lathe's shape cycles (lathe_shapes.h): reading the shape program as it
// runs, and running the path lathe_roughing.h makes of it.
#include "lathe_shapes.h"

#include <mbc/arith.h>

#include <fmt/format.h>

#include <algorithm>

#include "corner_state.h"
#include "cutter_comp.h"
#include "cutter_comp_state.h"
#include "lathe_codes.h"
#include "lathe_roughing.h"
#include "lathe_settings.h"
#include "lathe_state.h"
#include "programmed_moves.h"

namespace mbc::rt {

namespace {

constexpr int kG70 = kLatheOwnCode + 700;
constexpr int kG71 = kLatheOwnCode + 710;
constexpr int kG72 = kLatheOwnCode + 720;
constexpr int kG73 = kLatheOwnCode + 730;

int writtenCode(const mbrt_ctx& ctx, int code) {
  return static_cast<int>(writtenLatheCode(ctx.profile.gCodeSystem, code));
}

/// A word of the cycle block as a length in input units: a literal without
/// decimal point counts increments (unless 3401#0 DPI).
std::optional<double> lengthWord(const mbrt_ctx& ctx, const FrameWords& words,
                                 char letter) {
  const mbrt_word* word = words.word(letter);
  if (word == nullptr) {
    return std::nullopt;
  }
  const double value = numeric(word->value);
  return word->kind == MBRT_WORD_INT_LITERAL && !ctx.profile.decimalPointInput
             ? value / ctx.inputScale()
             : value;
}

std::optional<double> wholeWord(const FrameWords& words, char letter) {
  const mbrt_word* word = words.word(letter);
  return word != nullptr ? std::optional(roundHalfAway(numeric(word->value)))
                         : std::nullopt;
}

/// A length setting in counts: the block's word `letter` when the cycle
/// is one block (the Series 10/11 format) and gives it, else `parameter`.
Counts lengthSetting(const mbrt_ctx& ctx, const FrameWords& words,
                     bool oneBlock, char letter, int parameter) {
  const std::optional<double> units =
      oneBlock ? lengthWord(ctx, words, letter) : std::nullopt;
  return units ? static_cast<Counts>(roundToLengthCounts(ctx, *units))
               : cycleLength(ctx, parameter);
}

void keepLength(mbrt_ctx& ctx, int parameter, std::optional<double> units) {
  if (units) {
    keepCycleLength(ctx, parameter,
                    static_cast<Counts>(roundToLengthCounts(ctx, *units)));
  }
}

/// The first block of G71, G72 or G73: settings that stay.
void keepSettings(mbrt_ctx& ctx, int code, const FrameWords& words) {
  if (code == kG73) {
    keepLength(ctx, 5135, lengthWord(ctx, words, 'U'));
    keepLength(ctx, 5136, lengthWord(ctx, words, 'W'));
    if (const auto divisions = wholeWord(words, 'R')) {
      ctx.lathe->cycleSettings[5137] = *divisions;
    }
    return;
  }
  keepLength(ctx, 5132, lengthWord(ctx, words, code == kG71 ? 'U' : 'W'));
  keepLength(ctx, 5133, lengthWord(ctx, words, 'R'));
}

ShapeMotion shapeMotion(int kind) {
  switch (kind) {
    case MBRT_MOTION_RAPID:
      return ShapeMotion::Rapid;
    case MBRT_MOTION_CW:
      return ShapeMotion::Clockwise;
    case MBRT_MOTION_CCW:
      return ShapeMotion::CounterClockwise;
    default:
      return ShapeMotion::Line;
  }
}

/// A move the motion sink saw, as a move of a shape.
ShapeMove shapeMoveOf(const mbrt_ctx& ctx, const mbrt_motion& motion) {
  const int x = ctx.axisOf('X');
  const int z = ctx.axisOf('Z');
  ShapeMove move;
  move.motion = shapeMotion(motion.kind);
  move.end = {motion.end[x] * ctx.axisScale(x),
              motion.end[z] * ctx.axisScale(z)};
  for (int i = 0; i < 2; ++i) {
    const int axis = ctx.axisOf(motion.center_axes[i]);
    const double counts = motion.center[i] * ctx.axisScale(axis);
    (axis == x ? move.center.x : move.center.z) = counts;
  }
  return move;
}

/// The motion sink while a shape is read: each move becomes part of it,
/// with the G40/G41/G42 a block of the shape gave (0: the cycle's).
void recordMove(void* user, const mbrt_motion* motion) {
  auto& ctx = *static_cast<mbrt_ctx*>(user);
  ShapeReading& reading = ctx.lathe->shapeReading;
  reading.feedSet = reading.feedSet || ctx.machine.feedInBlock;
  ShapeMove move = shapeMoveOf(ctx, *motion);
  move.feed =
      reading.feedSet && move.motion != ShapeMotion::Rapid ? motion->feed : 0.0;
  const int compensation = ctx.machine.modal.compensation;
  move.compensation = compensation != reading.before.machine.modal.compensation
                          ? compensation
                          : 0;
  move.line = ctx.run.block.line;
  if (reading.shape.moves.empty() && ctx.run.block.file != nullptr) {
    reading.shape.file = ctx.run.block.file;
  }
  reading.shape.moves.push_back(move);
}

/// Runs a cycle's path from the current position, its moves marked with
/// the cycle; a move without a feed of its own takes `feed`, one without a
/// G40/G41/G42 of its own `compensation`. A move of a block of the shape
/// in `file` runs at that block's line, as the control runs blocks ns to
/// nf in G70: an alarm points at the block, called from the cycle's.
mbrt_status runMoves(mbrt_ctx& ctx, const std::vector<ShapeMove>& moves,
                     int code, double feed, int compensation,
                     const std::string* file) {
  const int x = ctx.axisOf('X');
  const int z = ctx.axisOf('Z');
  const ModalState modal = ctx.machine.modal;
  const bool codeInBlock = ctx.compensation->codeInBlock;
  ctx.compensation->codeInBlock = false;
  ctx.run.cycleLabel = writtenCode(ctx, code);
  const BlockPlace cycle{ctx.run.block.file, ctx.run.block.line};
  ctx.run.cycleBlock = cycle;
  ctx.machine.modal.incremental = false;
  mbrt_status status = 0;
  for (const ShapeMove& move : moves) {
    const bool ofShape = file != nullptr && move.line != 0;
    ctx.run.block.file = ofShape ? file->c_str() : cycle.file;
    ctx.run.block.line = ofShape ? move.line : cycle.line;
    ctx.machine.modal.feed = move.feed > 0.0 ? move.feed : feed;
    ctx.machine.modal.compensation =
        move.compensation != 0 ? move.compensation : compensation;
    AxisCounts target = ctx.machine.program;
    target[x] = static_cast<Counts>(roundHalfAway(move.end.x));
    target[z] = static_cast<Counts>(roundHalfAway(move.end.z));
    if (move.motion == ShapeMotion::Rapid || move.motion == ShapeMotion::Line) {
      status = moveLine(ctx, target, move.motion == ShapeMotion::Rapid);
    } else {
      AxisCounts center = ctx.machine.program;
      center[x] = static_cast<Counts>(roundHalfAway(move.center.x));
      center[z] = static_cast<Counts>(roundHalfAway(move.center.z));
      status = moveArcAbout(ctx, target, center,
                            move.motion == ShapeMotion::Clockwise);
    }
    if (status != 0) {
      break;
    }
  }
  ctx.run.block.file = cycle.file;
  ctx.run.block.line = cycle.line;
  ctx.run.cycleBlock = BlockPlace{};
  ctx.run.cycleLabel = 0;
  ctx.compensation->codeInBlock = codeInBlock;
  const double lastFeed = ctx.machine.modal.feed;
  ctx.machine.modal = modal;
  ctx.machine.modal.feed = code == kG70 ? lastFeed : modal.feed;
  return status;
}

/// G70 along a shape: its moves, then back to the start point at rapid,
/// which cancels the offset vector of tool nose radius compensation.
mbrt_status finish(mbrt_ctx& ctx, const Shape& shape) {
  const int x = ctx.axisOf('X');
  const int z = ctx.axisOf('Z');
  std::vector<ShapeMove> moves = shape.moves;
  ShapeMove back;
  back.motion = ShapeMotion::Rapid;
  back.end = {static_cast<double>(ctx.machine.program[x]),
              static_cast<double>(ctx.machine.program[z])};
  back.compensation = 40;
  moves.push_back(back);
  return runMoves(ctx, moves, kG70, ctx.machine.modal.feed,
                  ctx.machine.modal.compensation, &shape.file);
}

DryRunState takeSnapshot(const mbrt_ctx& ctx) {
  return {ctx.machine, ctx.host.motionSink};
}

void restoreSnapshot(mbrt_ctx& ctx, const DryRunState& snapshot) {
  ctx.machine = snapshot.machine;
  ctx.host.motionSink = snapshot.motionSink;
}

/// Whether a shape runs under tool nose radius compensation, in part or
/// whole, with the cycle's G40/G41/G42 `compensation`.
bool compensated(const Shape& shape, int compensation) {
  return std::any_of(shape.moves.begin(), shape.moves.end(),
                     [&](const ShapeMove& move) {
                       return (move.compensation != 0 ? move.compensation
                                                      : compensation) != 40;
                     });
}

struct PathCollector {
  const mbrt_ctx* ctx;
  std::vector<ShapeMove>* moves;
};

void collectMove(void* user, const mbrt_motion* motion) {
  const auto& collector = *static_cast<PathCollector*>(user);
  collector.moves->push_back(shapeMoveOf(*collector.ctx, *motion));
}

/// The path of the tool's control point along a shape under tool nose
/// radius compensation (0i-TF manual, G71-G73 with G41/G42: the cycle
/// roughs the compensated shape): from A without a vector to the end of
/// nf with the vector perpendicular to its move. A dry run of the shape's
/// moves through the compensation: nothing moves, nothing counts.
mbrt_status compensatedPath(mbrt_ctx& ctx, int code, const Shape& shape,
                            Shape& path) {
  const DryRunState before = takeSnapshot(ctx);
  const CompensationState compensation = *ctx.compensation;
  path = Shape{shape.start, {}, {}};
  PathCollector collector{&ctx, &path.moves};
  ctx.host.motionSink = {collectMove, &collector};
  ctx.run.dryRun = true;
  mbrt_status status = runMoves(ctx, shape.moves, code, ctx.machine.modal.feed,
                                ctx.machine.modal.compensation, &shape.file);
  if (status == 0) {
    status = releaseHeldMoves(ctx);
  }
  ctx.run.dryRun = false;
  *ctx.compensation = compensation;
  restoreSnapshot(ctx, before);
  return status;
}

/// After nf: the cycle runs over the shape read.
mbrt_status runCycle(mbrt_ctx& ctx) {
  ShapeReading& reading = ctx.lathe->shapeReading;
  const int code = ctx.run.shapeCycle;
  const Shape shape = reading.shape;
  const ShapePoint allowance = reading.allowance;
  const ShapePoint relief = reading.relief;
  const int divisions = reading.divisions;
  restoreSnapshot(ctx, reading.before);
  ctx.run.shapeCycle = 0;
  // G70 runs the kept shape: its moves' file lives as long as it.
  const Shape& kept = ctx.lathe->shapes[{reading.ns, reading.nf}] = shape;
  if (code == kG70) {
    return finish(ctx, kept);
  }
  const Roughing roughing{code == kG72, reading.typeTwo,
                          static_cast<double>(reading.depth),
                          static_cast<double>(reading.escape), allowance};
  if (code != kG73) {
    if (roughing.depth <= 0.0) {
      return raise(ctx, AlarmId::IllegalRepetitiveCycle,
                   fmt::format("G{}: the depth of cut must be greater than 0",
                               writtenCode(ctx, code)));
    }
    if (reading.typeTwo) {
      sendMessage(ctx,
                  fmt::format("G{} P{} Q{} type II: the pockets are cut "
                              "nearest first, each to its bottom; the "
                              "moves between cuts are reconstructed "
                              "(docs/language.md)",
                              writtenCode(ctx, code), reading.ns, reading.nf));
    }
  }
  Shape cut = shape;
  if (compensated(shape, ctx.machine.modal.compensation)) {
    if (const mbrt_status status = compensatedPath(ctx, code, shape, cut)) {
      return status;
    }
  }
  std::vector<ShapeMove> path;
  if (code == kG73) {
    repeatShape(cut, allowance, relief, divisions, path);
  } else if (roughShape(cut, roughing, path) == ShapeFault::NotMonotonic) {
    return raise(ctx, AlarmId::ShapeNotMonotonic,
                 fmt::format("G{} P{} Q{}: the shape turns back {} the cuts",
                             writtenCode(ctx, code), reading.ns, reading.nf,
                             roughing.pockets ? "along" : "across"));
  }
  return runMoves(ctx, path, code, ctx.machine.modal.feed, 40, nullptr);
}

/// Reading starts: the state the shape's blocks will run over is kept.
void startReading(mbrt_ctx& ctx, int code, double ns, double nf) {
  ShapeReading& reading = ctx.lathe->shapeReading;
  reading = ShapeReading{};
  ctx.run.shapeCycle = code;
  reading.ns = ns;
  reading.nf = nf;
  const int x = ctx.axisOf('X');
  const int z = ctx.axisOf('Z');
  reading.shape.start = {static_cast<double>(ctx.machine.program[x]),
                         static_cast<double>(ctx.machine.program[z])};
  reading.before = takeSnapshot(ctx);
  reading.cycleBlock = {ctx.run.block.file, ctx.run.block.line};
}

} // namespace

mbrt_status startShapeCycle(mbrt_ctx& ctx, int code, const FrameWords& words) {
  const std::optional<double> ns = wholeWord(words, 'P');
  const std::optional<double> nf = wholeWord(words, 'Q');
  // The Series 10/11 format's G71-G73 are one block, with the settings.
  const bool oneBlock = seriesTenFormat(ctx) && code != kG70;
  if (!ns || !nf) {
    if (code == kG70 || ns || nf || oneBlock) {
      return raise(
          ctx, AlarmId::ShapeAddressMissing,
          fmt::format("G{} needs P (the shape's first sequence number) and Q "
                      "(its last){}",
                      writtenCode(ctx, code),
                      !oneBlock ? ""
                      : code == kG73
                          ? ": in the Series 10/11 format (parameter 0001#1 "
                            "FCV) it is one block, P Q I K U W D F"
                          : ": in the Series 10/11 format (parameter 0001#1 "
                            "FCV) it is one block, P Q U W D F"));
    }
    keepSettings(ctx, code, words);
    return 0;
  }
  if (const mbrt_status status = cancelVectorHere(ctx)) {
    return status;
  }
  if (code == kG70) {
    if (const auto shape = ctx.lathe->shapes.find({*ns, *nf});
        shape != ctx.lathe->shapes.end()) {
      return finish(ctx, shape->second);
    }
  }
  startReading(ctx, code, *ns, *nf);
  ShapeReading& reading = ctx.lathe->shapeReading;
  const int x = ctx.axisOf('X');
  const int z = ctx.axisOf('Z');
  if (const auto u = lengthWord(ctx, words, 'U')) {
    reading.allowance.x = roundToAxisCounts(ctx, x, *u);
  }
  if (const auto w = lengthWord(ctx, words, 'W')) {
    reading.allowance.z = roundToAxisCounts(ctx, z, *w);
  }
  // D: G73's divisions, G71/G72's depth in least increments.
  const std::optional<double> d =
      oneBlock ? wholeWord(words, 'D') : std::nullopt;
  if (code == kG73) {
    reading.relief = {
        static_cast<double>(lengthSetting(ctx, words, oneBlock, 'I', 5135)),
        static_cast<double>(lengthSetting(ctx, words, oneBlock, 'K', 5136))};
    reading.divisions = static_cast<int>(d.value_or(cycleSetting(ctx, 5137)));
    if (reading.divisions < 1) {
      ctx.run.shapeCycle = 0;
      return raise(ctx, AlarmId::IllegalRepetitiveCycle,
                   fmt::format("G{}: {} divisions", writtenCode(ctx, code),
                               reading.divisions));
    }
  } else if (code != kG70) {
    reading.depth = d ? incrementCounts(ctx, *d) : cycleLength(ctx, 5132);
    reading.escape = cycleLength(ctx, 5133);
  }
  return 0;
}

void readShapeWords(mbrt_ctx& ctx, std::uint32_t axisMask) {
  ShapeReading& reading = ctx.lathe->shapeReading;
  if (reading.firstWordsRead) {
    return;
  }
  reading.firstWordsRead = true;
  const int cutAxis = ctx.axisOf(ctx.run.shapeCycle == kG72 ? 'X' : 'Z');
  reading.typeTwo =
      (ctx.run.shapeCycle == kG71 || ctx.run.shapeCycle == kG72) &&
      (axisMask >> cutAxis & 1) != 0;
}

mbrt_status enterShapeBlock(mbrt_ctx& ctx, std::optional<double> n) {
  ShapeReading& reading = ctx.lathe->shapeReading;
  if (!reading.started) {
    if (n != reading.ns) {
      const int code = ctx.run.shapeCycle;
      ctx.run.shapeCycle = 0;
      return raise(ctx, AlarmId::Unsupported,
                   fmt::format("G{} P{}: a shape program that is not the "
                               "blocks right after the cycle (mbc reads "
                               "the shape as it runs)",
                               writtenCode(ctx, code), reading.ns));
    }
    reading.started = true;
  }
  ctx.host.motionSink = {recordMove, &ctx};
  return 0;
}

mbrt_status leaveShapeBlock(mbrt_ctx& ctx, std::optional<double> n,
                            const mbrt_flow& flow, mbrt_status status) {
  ShapeReading& reading = ctx.lathe->shapeReading;
  ctx.host.motionSink = reading.before.motionSink;
  // A shape that cannot be read leaves the machine where the cycle found
  // it, for a context that runs again.
  const auto stop = [&] {
    restoreSnapshot(ctx, reading.before);
    ctx.run.shapeCycle = 0;
  };
  if (status != 0) {
    stop();
    return status;
  }
  if (flow.kind != MBRT_FLOW_NEXT) {
    stop();
    return raise(ctx, AlarmId::ShapeCommand,
                 "a call, return or end in the shape program");
  }
  if (n == reading.nf && ctx.corner->pending) {
    ctx.corner->pending = false;
    stop();
    return raise(ctx, AlarmId::MissingMoveAfterCorner,
                 fmt::format("N{}: the shape's last block ends with a "
                             "chamfer or corner R",
                             reading.nf));
  }
  const std::vector<ShapeMove>& moves = reading.shape.moves;
  if (n == reading.ns &&
      (moves.empty() || (moves.front().motion != ShapeMotion::Rapid &&
                         moves.front().motion != ShapeMotion::Line))) {
    stop();
    return raise(ctx, AlarmId::ShapeFirstBlock,
                 fmt::format("N{}: the first block of the shape must move "
                             "with G00 or G01",
                             reading.ns));
  }
  if (n != reading.nf) {
    return 0;
  }
  // The cycle's moves are its block's, as the blocks of the shape were
  // read on the way.
  const BlockPlace nf{ctx.run.block.file, ctx.run.block.line};
  ctx.run.block.file = reading.cycleBlock.file;
  ctx.run.block.line = reading.cycleBlock.line;
  const mbrt_status cycleStatus = runCycle(ctx);
  ctx.run.block.file = nf.file;
  ctx.run.block.line = nf.line;
  return cycleStatus;
}

} // namespace mbc::rt

// The private state behind the C ABI handle mbrt_ctx: profile data,
// variables, call levels, modal state, positions, sinks and the pending
// alarm, plus the helpers the runtime's source files share.
#pragma once

#include <mbc/addresses.h>
#include <mbc/alarm.h>
#include <mbc/direct_storage.h>
#include <mbc/engine.h>
#include <mbc/value.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "last_words.h"
#include "profile.h"

namespace mbc::rt {

inline constexpr int kCommonEnd = kLastNonvolatile + 1; // commons: #100..#999
static_assert(sizeof(mbrt_level::value) / sizeof(mbrt_num) == kLocalCount,
              "direct_storage.h's call level holds the locals of limits.h");
inline constexpr double kCountsPerDegree = 1000.0; // 0.001 deg (IS-B)
inline constexpr std::uint64_t kDefaultMaxBlocks = 100'000'000;
inline constexpr std::uint64_t kDefaultMaxOutput = std::uint64_t{1} << 30;

/// Positions and offsets are kept as whole counts of the least input
/// increment, so that output is exact and G91 moves do not drift.
using Counts = std::int64_t;
using AxisCounts = std::array<Counts, MBRT_MAX_AXES>;

/// One macro call level: the C struct compiled code addresses directly.
struct LocalLevel : mbrt_level {
  LocalLevel() : mbrt_level{} { std::fill_n(value, kLocalCount, vacant()); }
};

inline constexpr int kCallMacroBit = 1; // mbrt_call_kind bits
inline constexpr int kCallCodeBit = 2;
inline constexpr int kCallModalBit = 4;

/// One active call: nesting checks, #4115, the rules of calls by codes and
/// modal calls, and the call stack of alarm reports.
struct CallRecord {
  std::string program;
  int programNumber = 0;
  int kind = MBRT_CALL_SUB;   // mbrt_call_kind
  int modalId = 0;            // MBRT_CALL_MODAL: the G66 that called
  const char* file = nullptr; // the calling block
  int line = 0;
};

struct CallSite {
  std::string program;
  std::string file;
  int line = 0;
};

struct PendingAlarm {
  AlarmId id = AlarmId::None;
  int macroNumber = 0;
  std::string detail; // for macro alarms: the message
  std::string file;
  int line = 0;
  std::vector<CallSite> stack; // innermost first
};

/// The drilling data of a canned cycle, kept from block to block until G80
/// or a group 01 code: levels on the drilling axis, in workpiece counts.
struct CycleData {
  Counts initial = 0; // the level when the cycle mode began (G98)
  bool hasR = false;
  Counts r = 0; // the R level (G99), the initial level when not given
  bool hasZ = false;
  Counts z = 0; // the hole bottom
  Counts q = 0; // peck depth (G73, G83) or shift (G76, G87)
  double p = 0; // dwell at the bottom, ms

  bool operator==(const CycleData&) const = default;
};

/// A lathe's single cycle (G90, G92, G94) keeps its end point and taper
/// from block to block while it is in force: workpiece counts (X a radius).
struct SingleCycleData {
  bool hasX = false;
  bool hasZ = false;
  Counts x = 0;
  Counts z = 0;
  Counts r = 0; // the taper: the cut's start less its end (radius or Z)

  bool operator==(const SingleCycleData&) const = default;
};

/// Modal G codes (#4001..) and F.
struct ModalState {
  int motion = 0; // 0 1 2 3; a lathe's 32, 90, 92, 94 (lathe_codes.h)
  int plane = 17;
  bool incremental = false;
  bool polar = false;    // G16: plane words are a radius and an angle
  int compensation = 40; // G40 G41 G42: cutter compensation (cutter_comp.h)
  bool inch = false;
  bool returnToR = false; // G99
  int cycle = 0;          // 73, 74, 76, 81..89; 0 for G80
  CycleData cycleData;
  bool rigidTapping = false;        // M29 given: G84/G74 tap rigidly, until G80
  int seriesFifteenTap = 0;         // 842, 843: the cycle is G84.2 / G84.3
  int cuttingMode = 64;             // G61 G62 G63 G64 (no effect here)
  int feedMode = 94;                // G93 G94 G95
  int workOffset = kFirstG54Offset; // index into workOffsets
  double feed = 0.0;                // modal F
  bool surfaceSpeed = false;        // G96: S is a surface speed (lathes)
  SingleCycleData singleCycle;

  bool operator==(const ModalState&) const = default;
};

/// The coordinate frames between a program and the machine (frames.h):
/// mirror, scaling and rotation take a program point into the workpiece
/// frame, to which the G52 local origin is added; work offsets, the G92
/// shift and the tool length offset make it a machine position.
struct Frames {
  AxisCounts local{};           // G52: the local origin in the workpiece system
  AxisCounts preset{};          // G92: the shift of every workpiece system
  std::uint32_t mirrorMask = 0; // G51.1: mirrored axes
  AxisValues mirrorCenter{};    // the mirror axis of each, program counts
  bool scaling = false;         // G51
  AxisValues scale{};           // magnification of each axis (1: none)
  AxisValues scaleCenter{};
  bool rotation = false; // G68
  int rotationAxes[2] = {0, 1};
  double angle = 0.0; // degrees, counter-clockwise in the plane
  double cosAngle = 1.0;
  double sinAngle = 0.0;
  double rotationCenter[2] = {0.0, 0.0};
  int lengthMode = 49; // 43, 44, 49
  int lengthAxis = -1; // the axis the tool length offset moves
  Counts length = 0;   // the offset on that axis, signed
  // A lathe's tool position offset (lathe_tools.h): the geometry and wear
  // of the offset the last T code selected, per axis.
  AxisCounts toolGeometry{};
  AxisCounts toolWear{};
  int toolGeometryNumber = 0; // the offsets they came from (0: none)
  int toolWearNumber = 0;
  // Under mirror, scaling or rotation: the program position the last
  // resync found (rounded back from the tool) and the workpiece point it
  // stands for, so that an axis a block leaves alone stays where the tool
  // is rather than be rounded through the transform again (frames.cpp).
  bool synced = false;
  AxisCounts syncedProgram{};
  AxisCounts syncedWork{};

  bool transforms() const { return mirrorMask != 0 || scaling || rotation; }

  bool operator==(const Frames&) const = default;
};

/// A block's place in the program text.
struct BlockPlace {
  const char* file = nullptr;
  int line = 0;
};

/// The toolpath's box in workpiece counts of one input unit (G20 and G21
/// change what a count is). A move costs no division: the summary divides
/// the extremes, and since dividing by a positive number keeps the order,
/// that is the box of the divided points.
struct CountsBox {
  bool any = false;
  AxisValues low{};
  AxisValues high{};

  bool operator==(const CountsBox&) const = default;
};

/// What the summary tells about the toolpath (mbrt_stats): lengths in mm,
/// the box in counts of G21 ([0]) and of G20 ([1]).
struct RunStats {
  double feedLength = 0.0;
  double rapidLength = 0.0;
  double seconds = 0.0;
  std::array<CountsBox, 2> box{};

  bool operator==(const RunStats&) const = default;
};

/// A G66/G66.1 (or modal custom G code) in force: what it calls.
struct ModalCall {
  int id = 0;
  int program = 0;
  long repeat = 1;
  bool everyBlock = false; // G66.1
  std::vector<mbrt_word> args;
};

/// The call an NC block asks its engine for, one per call level: the
/// arguments stay valid while the engine repeats the call.
struct BlockCall {
  std::vector<mbrt_word> args;
  int modalId = 0;
  bool everyBlock = false;
};

/// The bytes a run has written against its limit (--max-output). Passing
/// the limit lowers the block limit to the blocks counted so far, so the
/// next block stops the run (compiled code already checks that limit at
/// every block); the alarm then names the block that passed it.
struct OutputBudget {
  std::uint64_t written = 0;
  std::uint64_t limit = kDefaultMaxOutput;
  const char* file = nullptr; // the block that passed the limit
  int line = 0;

  bool passed() const { return written > limit; }
};

template <class Fn> struct Sink {
  Fn fn = nullptr;
  void* user = nullptr;
};

/// A flag a signal handler or another thread sets while the run reads it.
/// It copies as a value, so that mbrt_reset can replace a whole context.
class SignalFlag {
public:
  SignalFlag() = default;

  SignalFlag(const SignalFlag& other) : value_(other.value_.load()) {}

  SignalFlag& operator=(const SignalFlag& other) {
    value_.store(other.value_.load());
    return *this;
  }

  SignalFlag& operator=(bool value) {
    value_.store(value);
    return *this;
  }

  operator bool() const { return value_.load(); }

private:
  std::atomic<bool> value_{false};
};

/// Where the tool is and what its next move starts from: its positions,
/// the modal state, the frames and the last words, and what the toolpath
/// has done so far (clock, moves, statistics). A run that must not count
/// (a lathe's shape program while it is read, the dry run that finds a
/// shape's compensated path) copies it whole and puts it back.
struct MachineState {
  AxisCounts position{}; // the control point in machine coordinates
  AxisCounts program{};  // the same point as the program sees it
  ModalState modal;
  // #4101..#4130 by index: the last value of each address (not in
  // ModalState, which a block with G codes copies).
  std::array<double, kLastWordCount> lastWords{};
  Frames frames;
  bool feedInBlock = false;  // the block has F (G93 needs it)
  AxisCounts skipPosition{}; // #5061: where the last G31 ended
  // The last G28/G30 intermediate point, for G29, and the axes it has (not
  // in ModalState: that is copied for every block).
  AxisCounts intermediate{};
  std::uint32_t intermediateMask = 0;
  // A lathe's maximum spindle speed in G96 (G50 S in G code system A,
  // G92 S in B and C), rpm; 0: none given.
  double spindleLimit = 0.0;
  // G34's K of the block running: the lead's change per revolution.
  double leadChange = 0.0;
  double clockMs = 0.0;    // #3001
  double clockHours = 0.0; // #3002, machine data: a reset keeps it
  std::uint64_t moves = 0;
  RunStats stats;

  /// The machine's power-on state (mbrt_reset_state): the tool at the
  /// machine origin, no frames (G92, G52, mirror, scaling, rotation, tool
  /// length offset), the power-on modal codes and the clock at 0. G20/G21
  /// stays until the units are switched back (switchUnits).
  void reset(const Profile& profile);

  /// A run begins as a control starts a program after RESET: the machine
  /// stays where the last run left it (position, modal codes, frames, F),
  /// except for what RESET cancels: canned cycles (G80) and cutter
  /// compensation (G40). With parameter 3402#6 CLR the modal codes go back
  /// to their power-on values (the control's clear state). Moves and
  /// statistics count from 0.
  void startRun(const Profile& profile);

  /// The power-on modal codes and no last words (#4101+); G20/G21 stays,
  /// as the control's clear state keeps it.
  void clearModalCodes(const Profile& profile);

  bool operator==(const MachineState&) const = default;
};

/// What a run that must not count puts back: the machine's state and
/// where moves went.
struct DryRunState {
  MachineState machine;
  Sink<mbrt_motion_fn> motionSink;
};

/// The machine's data, which runs keep and mbrt_reset takes back from the
/// profile: offsets, common variables, interface signals, part counters,
/// settings and the parameters as the profile gave them.
struct MachineData {
  std::array<Num, kCommonEnd> commons{};
  // #98000-#98499, when the profile has them.
  std::array<Num, kLastCommon98000 - kFirstCommon98000 + 1> commons98000{};
  // UO000-UO031 (#1132; bits 0-15 are #1100-#1115) and UO100-UO131 (#1133).
  std::array<std::uint32_t, 4> outputWords{}; // UO000-UO031 ... UO300-UO331
  std::array<std::uint32_t, 4> inputWords{};  // UI000-UI031 ... UI300-UI331
  std::vector<ToolOffset> toolOffsets;
  std::vector<LatheOffset> latheOffsets; // a lathe's instead
  std::vector<AxisCounts> workOffsets;
  double settingBits = 0.0;   // #3005
  double partsCount = 0.0;    // #3901
  double partsRequired = 0.0; // #3902
  // The parameters as the profile gave them: a program may set others
  // (G10 L52), and mbrt_reset brings these back.
  std::map<int, double> profileParameters;
  std::map<int, AxisValues> profileAxisParameters;
};

/// The programs a run is in: the main program, the call levels with their
/// locals, the modal calls in force and the calls blocks ask for.
struct CallStack {
  std::vector<LocalLevel> levels; // back() is the current level
  std::vector<CallRecord> calls;
  std::vector<ModalCall> modalCalls; // G66 in force, innermost last
  int nextModalId = 1;
  std::deque<BlockCall> blockCalls; // by call level
  // The M, T, S or B code of the block that called a subprogram ('\0':
  // none), so that the flattened program leaves it out.
  std::pair<char, double> callingCode{'\0', 0.0};
  int macroDepth = 0;
  int subDepth = 0;
  std::string mainProgram;
  int mainProgramNumber = 0;
  double entrySequence = 0.0; // mbrt_entry_sequence

  /// A run of `program` begins: its main program's level and no calls.
  void startRun(const char* program);
};

/// The run as the host and the control steer it: the block being executed
/// and the count of blocks, the limits, signals that stop it, the first
/// alarm, and the switches an operator sets.
struct RunControl {
  // A signal handler or another thread lowers block.max_blocks to stop the
  // run (mbrt_interrupt, mbrt_out_of_memory), so it is read and written
  // atomically.
  mbrt_block_state block{nullptr, 0, 0, 0, kDefaultMaxBlocks};
  // The N of the block running, -1 for none: the flattened program keeps
  // it, for a lathe's shape cycles and a reader's bearings.
  double blockSequence = -1.0;
  // The cycle whose moves run now (a lathe's single and shape cycles): the
  // label its moves carry, 0 for none, and while a shape cycle runs the
  // moves of its shape's blocks, each at its block's line, the cycle's
  // block, which an alarm names as the caller.
  int cycleLabel = 0;
  BlockPlace cycleBlock;
  // A lathe's shape cycle (G70-G73, lathe_codes.h) reading the blocks of
  // its shape program (lathe_shapes.h), 0 for none: their moves make the
  // shape, not the tool's path, so the stages below neither compensate
  // them nor check their feed.
  int shapeCycle = 0;
  // The dry run that finds a shape's compensated path (lathe_shapes.cpp):
  // its moves are no tool's, so no stroke limit stops them.
  bool dryRun = false;
  SignalFlag interrupted;
  SignalFlag outOfMemory;
  bool illegalMainNumber = false; // PS0074 at the first block
  // Sinks being called (motion, text, alarm), and the first call that
  // would have restarted, reset or freed the context from inside one.
  int sinkDepth = 0;
  const char* refusedInSink = nullptr;
  std::uint64_t maxBlocks = kDefaultMaxBlocks; // --max-blocks
  OutputBudget output;
  unsigned skipMask = 0; // optional block skip switches: bit n for /n
  std::uint64_t optionalStops = 0;
  bool mainM99 = false;
  PendingAlarm alarm;
  // G10 L52 ... G11: each block sets a parameter (parameter_input.h).
  bool parameterInput = false;
  double singleBlockBits = 0.0;     // #3003
  double feedHoldBits = 0.0;        // #3004
  double date = 0.0;                // #3011
  double timeOfDay = 0.0;           // #3012
  std::string scratch;              // reused output buffer
  std::string gcodeLine;            // the flattened block being written
  std::vector<mbrt_word> stepWords; // mbrt_nc_steps' words of one block

  /// A run begins from nothing run yet: no blocks counted, no alarm, no
  /// signal to stop, #3003/#3004 off and today's #3011/#3012; what the
  /// host set (keepHostSettings) and the buffers stay. `illegalMainNumber`: the
  /// main program's number is one the machine cannot have, so the run alarms at
  /// its first block.
  void startRun(bool illegalMainNumber);

  bool readingShape() const { return shapeCycle != 0; }

  /// Sets the block limit; atomic because mbrt_interrupt may store to it
  /// from a signal handler or another thread.
  void setBlockLimit(std::uint64_t blocks) {
    std::atomic_ref(block.max_blocks).store(blocks, std::memory_order_relaxed);
  }

  /// Takes what the host set on `from`: tracing, the block and output
  /// limits and the block skip switches.
  void keepHostSettings(const RunControl& from);
};

/// Where a run's output goes, as the host set it: the sinks, the motions
/// buffered for it, and the names of the programs it loaded.
struct HostOutputs {
  Sink<mbrt_text_fn> alarmSink;
  std::vector<mbrt_motion> motionBuffer; // mbrt_buffer_motions
  std::set<std::string> bufferedNames;   // their program names, stable
  Sink<mbrt_motion_fn> motionSink;
  Sink<mbrt_text_fn> printSink;
  Sink<mbrt_text_fn> messageSink;
  Sink<mbrt_text_fn> traceSink;
  Sink<mbrt_text_fn> gcodeSink; // the flattened program
  // What a sink that writes on a thread of its own counted beyond the
  // exact bytes, asked for when the count passes the output limit.
  Sink<mbrt_settle_fn> outputSettle;
  /// "<DRILL>" for the number a call by name carries (mbrt_name_programs).
  std::map<int, std::string> programNames;

  /// A run begins with no motions buffered.
  void startRun();
};

// The parts of a context that a feature of the machine owns, declared
// where the feature lives: the context holds them, and only code that
// includes their header reads them.
struct CompensationState; // moves/cutter_comp_state.h
struct CornerInsertion;   // moves/corner_state.h
struct LatheState;        // lathe/lathe_state.h

} // namespace mbc::rt

/// A context: the machine's description and the parts of its state, each
/// with its own life (core/context.cpp, api/lifetime.cpp). Its special
/// members are defined where every part is complete (api/lifetime.cpp).
struct mbrt_ctx {
  mbrt_ctx();
  ~mbrt_ctx();
  mbrt_ctx(const mbrt_ctx&) = delete;
  mbrt_ctx& operator=(const mbrt_ctx&) = delete;
  mbrt_ctx(mbrt_ctx&&) noexcept;
  mbrt_ctx& operator=(mbrt_ctx&&) noexcept;

  mbc::rt::Profile profile;
  std::array<std::int8_t, 26> axisIndex{}; // 'A'..'Z' -> axis or -1
  mbc::rt::MachineData data;
  mbc::rt::CallStack stack;
  mbc::rt::MachineState machine;
  std::unique_ptr<mbc::rt::CompensationState> compensation;
  std::unique_ptr<mbc::rt::CornerInsertion> corner;
  std::unique_ptr<mbc::rt::LatheState> lathe;
  mbc::rt::RunControl run;
  mbc::rt::HostOutputs host;

  int axisCount() const { return static_cast<int>(profile.axes.size()); }

  int axisOf(char letter) const {
    return letter >= 'A' && letter <= 'Z' ? axisIndex[letter - 'A'] : -1;
  }

  /// Least input increments per unit: 1000 (0.001 mm) or 10000 (0.0001
  /// inch).
  double inputScale() const { return inputScale(machine.modal.inch); }

  static double inputScale(bool inch) { return inch ? 10000.0 : 1000.0; }

  /// Counts per least input increment: 2 on a machine with an axis
  /// programmed as a diameter, whose increment (0.001 mm of diameter) is
  /// half an increment of its radius. Geometry works on radii, so every
  /// linear count is that half increment there.
  int countsPerIncrement() const { return profile.diameterMask != 0 ? 2 : 1; }

  /// Counts per input unit of a radius or a length.
  double scale() const { return scale(machine.modal.inch); }

  double scale(bool inch) const {
    return inputScale(inch) * countsPerIncrement();
  }

  bool isRotary(int axis) const {
    return (profile.rotaryMask >> axis & 1) != 0;
  }

  /// The axis an incremental address moves on a lathe in G code system A
  /// (U: X, V: Y, W: Z, H: C), -1 for other letters and machines.
  int incrementalAxisOf(char letter) const {
    if (!profile.lathe() || profile.gCodeSystem != 'A' || axisOf(letter) >= 0) {
      return -1;
    }
    switch (letter) {
      case 'U':
        return axisOf('X');
      case 'V':
        return axisOf('Y');
      case 'W':
        return axisOf('Z');
      case 'H':
        return axisOf('C');
      default:
        return -1;
    }
  }

  /// The axis an address moves, absolute or incremental.
  int movedAxisOf(char letter) const {
    const int axis = axisOf(letter);
    return axis >= 0 ? axis : incrementalAxisOf(letter);
  }

  bool isDiameter(int axis) const {
    return (profile.diameterMask >> axis & 1) != 0;
  }

  /// Counts per unit of an axis as programs write it and the control shows
  /// it: a rotary axis counts 0.001 degree whatever G20/G21, a diameter
  /// axis counts its radius, so a unit of diameter is half the counts.
  double axisScale(int axis) const {
    return axisScale(axis, machine.modal.inch);
  }

  double axisScale(int axis, bool inch) const {
    return axisIncrements(axis, inch) * axisCountsPerIncrement(axis);
  }

  /// Least input increments per unit of an axis: 0.001 degree on a rotary
  /// axis whatever G20/G21. A block's axis word is rounded to them; kept
  /// apart from axisScale so that reading one costs no division.
  double axisIncrements(int axis) const {
    return axisIncrements(axis, machine.modal.inch);
  }

  double axisIncrements(int axis, bool inch) const {
    return isRotary(axis) ? mbc::rt::kCountsPerDegree : inputScale(inch);
  }

  /// Counts per least input increment of an axis.
  int axisCountsPerIncrement(int axis) const {
    return isRotary(axis) || isDiameter(axis) ? 1 : countsPerIncrement();
  }

  bool rollsOver(int axis) const {
    return (profile.rolloverMask >> axis & 1) != 0;
  }

  /// Counts of one rotation of an axis that rolls over (1260).
  mbc::rt::Counts rotation(int axis) const {
    const auto turn = static_cast<mbc::rt::Counts>(
        std::round(profile.rotationDegrees[axis] * mbc::rt::kCountsPerDegree));
    // Less than an increment: a full circle, as 0 is.
    return turn > 0 ? turn
                    : static_cast<mbc::rt::Counts>(360.0 *
                                                   mbc::rt::kCountsPerDegree);
  }

  /// A position as the control shows it: within one rotation on an axis
  /// that rolls over (mbc keeps the turns made, unseen).
  mbc::rt::Counts shown(int axis, mbc::rt::Counts counts) const {
    if (!rollsOver(axis)) {
      return counts;
    }
    const mbc::rt::Counts turn = rotation(axis);
    return (counts % turn + turn) % turn;
  }

  /// Counts per unit of an axis in the summary's box, in G20 (`inch`) or
  /// G21: mm, or degrees.
  double boxScale(int axis, bool inch) const {
    if (isRotary(axis)) {
      return mbc::rt::kCountsPerDegree;
    }
    return countsPerMm(inch) / (isDiameter(axis) ? 2.0 : 1.0);
  }

  int decimals() const { return machine.modal.inch ? 4 : 3; }

  /// Counts per mm, for parameters given in mm whatever the input unit.
  double countsPerMm() const { return countsPerMm(machine.modal.inch); }

  double countsPerMm(bool inch) const {
    return (inch ? 10000.0 / 25.4 : 1000.0) * countsPerIncrement();
  }

  mbc::rt::LocalLevel& locals() { return stack.levels.back(); }

  const char* programName() const {
    return stack.calls.empty() ? stack.mainProgram.c_str()
                               : stack.calls.back().program.c_str();
  }

  int programNumber() const {
    return stack.calls.empty() ? stack.mainProgramNumber
                               : stack.calls.back().programNumber;
  }
};

namespace mbc::rt {

/// Records an alarm with the current block and call stack; the first alarm
/// of a run is kept. Returns the id as an mbrt_status.
mbrt_status raise(mbrt_ctx& ctx, AlarmId id, std::string_view detail = {},
                  int macroNumber = 0);

/// raise at another block than the one running: a move that waited for
/// later blocks alarms at its own.
mbrt_status raiseAt(mbrt_ctx& ctx, const BlockPlace& place, AlarmId id,
                    std::string_view detail);

/// "file:line: ", or "" without a file: how alarms, messages and trace
/// lines name the block.
std::string locationPrefix(const std::string& file, int line);

/// Sends "file:line: message: text\n" to the message sink.
void sendMessage(mbrt_ctx& ctx, std::string_view text);

/// Counts bytes written by the run against its output limit (--max-output).
void countOutput(mbrt_ctx& ctx, std::uint64_t bytes);

/// Calls a sink of the context: inside it the calls that would restart,
/// reset or free the context refuse (refuseInSink).
template <typename Call> void callSink(mbrt_ctx& ctx, Call&& call) {
  ++ctx.run.sinkDepth;
  call();
  --ctx.run.sinkDepth;
}

/// True when `function` is called from inside one of the context's sinks:
/// it must not run, and the run stops before its next block with MBC0007.
bool refuseInSink(mbrt_ctx& ctx, const char* function);

/// The C API's snprintf contract: as much of `text` as fits in `buf`
/// (`size` bytes with the terminating NUL; nothing when NULL or 0), and the
/// whole length. Allocates nothing.
size_t copyText(std::string_view text, char* buf, size_t size);

/// Sends text to one of the context's text sinks, if set, and counts it.
void sendText(mbrt_ctx& ctx, const Sink<mbrt_text_fn>& sink,
              std::string_view text);

/// The alarm of a run whose output passed its limit, at the block that
/// passed it.
mbrt_status raiseOutputLimit(mbrt_ctx& ctx);

/// 1000 for "O1000", 0 for "<NAME>", "MAIN" and anything else.
int parseProgramNumber(const char* name);

/// PS0074 for a program number the machine cannot have (more than four
/// digits on a profile with program_number_digits 4).
mbrt_status checkProgramNumber(mbrt_ctx& ctx, double number);

/// Rounds `value` (input units) half away from zero to counts of the least
/// increment. A decimal tie such as 2.0005 lands a few ulps off .5 after the
/// multiplication; it is taken as the tie the program wrote.
inline double roundToCounts(double value, double scale) {
  const double x = std::fabs(value * scale);
  double whole = std::floor(x);
  if (x - whole >= 0.5 - 8 * DBL_EPSILON * x) {
    whole += 1.0;
  }
  return value < 0 ? -whole : whole;
}

/// A value in an axis's units (a diameter on a diameter axis) to counts:
/// rounded to the least input increment first, as the control reads it.
inline double roundToAxisCounts(const mbrt_ctx& ctx, int axis, double value) {
  const int per = ctx.axisCountsPerIncrement(axis);
  return roundToCounts(value, ctx.axisIncrements(axis)) * per;
}

/// A radius or length in input units to counts, rounded to the increment.
inline double roundToLengthCounts(const mbrt_ctx& ctx, double value) {
  return roundToCounts(value, ctx.inputScale()) * ctx.countsPerIncrement();
}

/// Least increments per unit of an address: 1000 or 10000 on axes, arc
/// centres, Q and F, 10 for G codes (G54.1), 1 for the others.
double addressCountsPerUnit(const mbrt_ctx& ctx, char letter);

/// FANUC addresses take at most nine digits (PS0003 beyond).
inline bool fitsAddress(double counts) {
  return std::fabs(counts) <= 999'999'999.0;
}

inline double countsToUnits(Counts counts, double scale) {
  return static_cast<double>(counts) / scale;
}

} // namespace mbc::rt

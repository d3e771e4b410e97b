// The machine's facts for mbc check (see machine_facts.h).
#include "toolchain/machine_facts.h"

#include <mbc/calling_codes.h>
#include <mbc/engine.h>

#include <algorithm>
#include <cmath>
#include <string_view>

namespace mbc::toolchain {

namespace {

double parameter(mbrt_ctx* ctx, int form, int number, int bit, int axis) {
  double value = 0;
  return mbrt_read_parameter(ctx, form, number, bit, axis, &value) == 0 ? value
                                                                        : 0;
}

bool bit(mbrt_ctx* ctx, int number, int n) {
  return (static_cast<long>(mbrt_parameter(ctx, number)) >> n & 1) != 0;
}

bool makesCodesCall(mbrt_ctx* ctx) {
  if (bit(ctx, 6001, 5) || bit(ctx, 6007, 4) || bit(ctx, 6007, 5)) {
    return true;
  }
  for (const CodeTable& table :
       {kCustomGCodes, kSubprogramMCodes, kMacroMCodes}) {
    for (int n = 0; n < table.size; ++n) {
      if (mbrt_parameter(ctx, table.firstParameter + n) != 0) {
        return true;
      }
    }
  }
  return false;
}

} // namespace

MachineFacts machineFacts(mbrt_ctx* ctx) {
  MachineFacts facts;
  mbrt_stats stats{};
  mbrt_get_stats(ctx, &stats);
  facts.axes = stats.axis_names;
  facts.inch = std::string_view(stats.unit) == "inch";
  facts.lathe = mbrt_lathe_system(ctx) != 0;
  facts.decimalPointInput = bit(ctx, 3401, 0);
  facts.lengthOnPlaneNormal = bit(ctx, 5001, 1);
  facts.codeCalls = makesCodesCall(ctx);
  const int axes = static_cast<int>(facts.axes.size());
  for (int axis = 0; axis < axes; ++axis) {
    const std::uint32_t mask = std::uint32_t{1} << axis;
    facts.rotaryMask |= parameter(ctx, MBRT_PARAMETER_BIT | MBRT_PARAMETER_AXIS,
                                  1006, 0, axis + 1) != 0
                            ? mask
                            : 0;
    double low = 0;
    double high = 0;
    facts.strokes.push_back(mbrt_get_stroke(ctx, axis, &low, &high) != 0
                                ? std::optional(Stroke{low, high})
                                : std::nullopt);
    for (int reference = 0; reference < 3; ++reference) {
      facts.references[static_cast<std::size_t>(reference)].push_back(
          parameter(ctx, MBRT_PARAMETER_AXIS, 1241 + reference, 0, axis + 1));
    }
    double position = 0;
    mbrt_get_machine_position(ctx, axis, &position);
    facts.position.push_back(position);
  }
  // The external offset moves every work coordinate system.
  for (std::size_t set = 1; set < facts.workOffsets.size(); ++set) {
    for (int axis = 0; axis < axes; ++axis) {
      double external = 0;
      double offset = 0;
      mbrt_get_work_offset(ctx, "EXT", axis, &external);
      mbrt_get_work_offset(ctx, mbrt_work_offset_set(static_cast<int>(set)),
                           axis, &offset);
      facts.workOffsets[set].push_back(external + offset);
    }
  }
  const int offsets = mbrt_tool_offset_count(ctx);
  facts.lengths.assign(static_cast<std::size_t>(offsets) + 1, 0.0);
  // Memory C has D values of their own; A and B give D the H value.
  bool radii = false;
  for (int i = 0; const char* field = mbrt_tool_offset_field(ctx, i); ++i) {
    radii = radii || std::string_view(field) == "d_geometry";
  }
  for (int n = 1; n <= offsets; ++n) {
    double radius = 0;
    for (int i = 0; const char* field = mbrt_tool_offset_field(ctx, i); ++i) {
      double value = 0;
      mbrt_get_tool_offset(ctx, n, field, &value);
      const std::string_view name = field;
      if (name == "h_geometry" || name == "h_wear") {
        facts.lengths[static_cast<std::size_t>(n)] += value;
      }
      if (name.substr(0, 2) == (radii ? "d_" : "h_")) {
        radius += value;
      }
    }
    facts.largestRadius = std::max(facts.largestRadius, std::fabs(radius));
  }
  return facts;
}

} // namespace mbc::toolchain

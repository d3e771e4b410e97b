// The variables of a lathe's offset memory (lathe_offset_vars.h).
#include "lathe_offset_vars.h"

#include <mbc/arith.h>

#include <fmt/format.h>

#include <array>

#include "flat_gcode.h"
#include "offset_keys.h"

namespace mbc::rt {

namespace {

struct OffsetSeries {
  int shortBase; // #shortBase + n, n up to shortCount
  int shortCount;
  int longBase; // #longBase + n
  double LatheOffset::*field;
};

constexpr int kShortCount = 64;
constexpr int kShortY = 49;

constexpr std::array kSeries = {
    OffsetSeries{2000, kShortCount, 10000, &LatheOffset::xWear},
    OffsetSeries{2100, kShortCount, 11000, &LatheOffset::zWear},
    OffsetSeries{2200, kShortCount, 12000, &LatheOffset::rWear},
    OffsetSeries{2300, kShortCount, 13000, &LatheOffset::tip},
    OffsetSeries{2400, kShortY, 14000, &LatheOffset::yWear},
    OffsetSeries{2450, kShortY, 19000, &LatheOffset::yGeometry},
    OffsetSeries{2700, kShortCount, 15000, &LatheOffset::xGeometry},
    OffsetSeries{2800, kShortCount, 16000, &LatheOffset::zGeometry},
    OffsetSeries{2900, kShortCount, 17000, &LatheOffset::rGeometry},
};

struct Found {
  const OffsetSeries* series = nullptr;
  int number = 0; // the offset number
};

Found findSeries(long n) {
  for (const OffsetSeries& series : kSeries) {
    if (n > series.shortBase && n <= series.shortBase + series.shortCount) {
      return {&series, static_cast<int>(n - series.shortBase)};
    }
    if (n > series.longBase && n < series.longBase + 1000) {
      return {&series, static_cast<int>(n - series.longBase)};
    }
  }
  return {};
}

/// The offset a variable names, or PS0115: no such series, a geometry
/// without geometry/wear memory, Y without a Y axis, or an offset number
/// beyond the machine's.
mbrt_status findOffset(mbrt_ctx& ctx, long n, Found* found) {
  *found = findSeries(n);
  const OffsetSeries* series = found->series;
  std::string why;
  if (series == nullptr) {
    why = "no lathe offset variable";
  } else if (latheOffsetKey(series->field).geometry &&
             !ctx.profile.geometryWear) {
    why = "geometry offsets need \"geometry_wear\"";
  } else if (latheOffsetKey(series->field).letter == 'Y' &&
             ctx.axisOf('Y') < 0) {
    why = "the machine has no Y axis";
  } else if (found->number > ctx.profile.toolOffsetCount) {
    why = fmt::format("offset {} (the machine has {})", found->number,
                      ctx.profile.toolOffsetCount);
  } else {
    return 0;
  }
  return raise(ctx, AlarmId::VariableOutOfRange,
               fmt::format("#{}: {}", n, why));
}

} // namespace

std::vector<LatheOffsetVariables> latheOffsetVariables() {
  std::vector<LatheOffsetVariables> rows;
  for (const OffsetSeries& series : kSeries) {
    rows.push_back({series.shortBase, series.shortCount, series.longBase,
                    latheOffsetKey(series.field).key});
  }
  return rows;
}

mbrt_status readLatheOffset(mbrt_ctx& ctx, long n, Num* out) {
  Found found;
  if (const mbrt_status status = findOffset(ctx, n, &found)) {
    return status;
  }
  *out = ctx.data.latheOffsets[static_cast<std::size_t>(found.number)].*
         found.series->field;
  return 0;
}

mbrt_status writeLatheOffset(mbrt_ctx& ctx, long n, Num value) {
  Found found;
  if (const mbrt_status status = findOffset(ctx, n, &found)) {
    return status;
  }
  const OffsetSeries& series = *found.series;
  const LatheOffsetKey& key = latheOffsetKey(series.field);
  double units = numeric(value);
  if (key.letter == 'Q') {
    units = roundHalfAway(units);
    if (units < 0.0 || units > 9.0) {
      return raise(ctx, AlarmId::ArgumentOutOfRange,
                   fmt::format("#{} = {}: the tip direction is 0 to 9", n,
                               numeric(value)));
    }
  } else {
    const double counts = roundToCounts(units, ctx.inputScale());
    if (!fitsAddress(counts)) {
      return raise(ctx, AlarmId::ArgumentOutOfRange,
                   fmt::format("tool offset {}", units));
    }
    units = countsToUnits(static_cast<Counts>(counts), ctx.inputScale());
  }
  ctx.data.latheOffsets[static_cast<std::size_t>(found.number)].*series.field =
      units;
  flattenLatheOffset(ctx, key.geometry ? 10000 + found.number : found.number,
                     key.letter, units);
  return 0;
}

} // namespace mbc::rt

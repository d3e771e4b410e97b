// The offset memory by the names of the machine profile, in the machine's
// unit (runtime.h, "The offset memory in the machine's unit"): what a state
// file saves and loads, whatever G20/G21 a run left in force.
#include <mbc/runtime.h>

#include <array>
#include <cmath>
#include <cstring>
#include <span>
#include <string>

#include "context.h"
#include "flat_gcode.h"
#include "frames.h"
#include "offset_keys.h"

namespace mbc::rt {

namespace {

/// The index of a work offset set, -1 for another name.
int setIndex(const char* set) {
  const std::optional<int> index =
      set != nullptr ? workOffsetIndex(set) : std::nullopt;
  return index.value_or(-1);
}

/// A value in the machine's unit, rounded to its least increment, in
/// counts; none when it has more than nine digits.
std::optional<double> machineCounts(double value, double increments,
                                    int perIncrement) {
  const double counts = roundToCounts(value, increments);
  if (!fitsAddress(counts)) {
    return std::nullopt;
  }
  return counts * perIncrement;
}

/// The entry of `keys` (offset_keys.h) named `name`, or nullptr.
template <class Key>
const Key* findField(std::span<const Key> keys, const char* name) {
  for (const Key& key : keys) {
    if (name != nullptr && std::strcmp(name, key.key) == 0) {
      return &key;
    }
  }
  return nullptr;
}

/// The name of the i-th entry of `keys`, or nullptr past the last.
template <class Key> const char* fieldName(std::span<const Key> keys, int i) {
  return i >= 0 && static_cast<std::size_t>(i) < keys.size() ? keys[i].key
                                                             : nullptr;
}

bool hasToolOffset(const mbrt_ctx& ctx, int number) {
  return number >= 1 && number <= ctx.profile.toolOffsetCount;
}

} // namespace

} // namespace mbc::rt

using namespace mbc::rt;

const char* mbrt_work_offset_set(int i) {
  static const auto kNames = [] {
    std::array<std::string, kWorkOffsetCount> names;
    for (int index = 0; index < kWorkOffsetCount; ++index) {
      names[static_cast<std::size_t>(index)] = workOffsetKey(index);
    }
    return names;
  }();
  return i >= 0 && i < kWorkOffsetCount
             ? kNames[static_cast<std::size_t>(i)].c_str()
             : nullptr;
}

int mbrt_get_work_offset(const mbrt_ctx* ctx, const char* set, int axis,
                         double* value) {
  const int index = setIndex(set);
  if (index < 0 || axis < 0 || axis >= ctx->axisCount()) {
    return 0;
  }
  *value = countsToUnits(ctx->data.workOffsets[index][axis],
                         ctx->axisScale(axis, ctx->profile.inch));
  return 1;
}

int mbrt_set_work_offset(mbrt_ctx* ctx, const char* set, int axis,
                         double value) {
  const int index = setIndex(set);
  if (index < 0 || axis < 0 || axis >= ctx->axisCount()) {
    return 0;
  }
  const int per = ctx->axisCountsPerIncrement(axis);
  const std::optional<double> counts =
      machineCounts(value, ctx->axisScale(axis, ctx->profile.inch) / per, per);
  if (!counts) {
    return 0;
  }
  ctx->data.workOffsets[index][axis] = static_cast<Counts>(*counts);
  if (index == ctx->machine.modal.workOffset || index == kExternalOffset) {
    resyncProgram(*ctx); // the machine stays
  }
  flattenWorkOffset(*ctx, index);
  return 1;
}

const char* mbrt_tool_offset_field(const mbrt_ctx* ctx, int i) {
  return ctx->profile.lathe()
             ? fieldName(latheOffsetKeys(ctx->profile.geometryWear), i)
             : fieldName(millOffsetKeys(ctx->profile.toolOffsetMemory), i);
}

int mbrt_get_tool_offset(const mbrt_ctx* ctx, int number, const char* field,
                         double* value) {
  if (!hasToolOffset(*ctx, number)) {
    return 0;
  }
  const auto n = static_cast<std::size_t>(number);
  if (ctx->profile.lathe()) {
    const LatheOffsetKey* key =
        findField(latheOffsetKeys(ctx->profile.geometryWear), field);
    if (key != nullptr) {
      *value = ctx->data.latheOffsets[n].*(key->field);
    }
    return key != nullptr;
  }
  const MillOffsetKey* key =
      findField(millOffsetKeys(ctx->profile.toolOffsetMemory), field);
  if (key != nullptr) {
    *value = ctx->data.toolOffsets[n].*(key->field);
  }
  return key != nullptr;
}

int mbrt_set_tool_offset(mbrt_ctx* ctx, int number, const char* field,
                         double value) {
  if (!hasToolOffset(*ctx, number)) {
    return 0;
  }
  const auto n = static_cast<std::size_t>(number);
  const double increments = ctx->inputScale(ctx->profile.inch);
  const std::optional<double> counts = machineCounts(value, increments, 1);
  if (ctx->profile.lathe()) {
    const LatheOffsetKey* key =
        findField(latheOffsetKeys(ctx->profile.geometryWear), field);
    const bool tip = key != nullptr && key->letter == 'Q';
    if (key == nullptr ||
        (tip && (value != std::floor(value) || value < 0 || value > 9)) ||
        (!tip && !counts)) {
      return 0;
    }
    const double units = tip ? value : *counts / increments;
    ctx->data.latheOffsets[n].*(key->field) = units;
    flattenLatheOffset(*ctx, key->geometry ? 10000 + number : number,
                       key->letter, units);
    return 1;
  }
  const MillOffsetKey* key =
      findField(millOffsetKeys(ctx->profile.toolOffsetMemory), field);
  if (key == nullptr || !counts) {
    return 0;
  }
  const double units = *counts / increments;
  ctx->data.toolOffsets[n].*(key->field) = units;
  flattenToolOffset(*ctx, key->l, number, units);
  return 1;
}

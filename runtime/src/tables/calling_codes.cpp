// The calling codes (see <mbc/calling_codes.h>).
#include <mbc/calling_codes.h>
#include <mbc/g_codes.h>

namespace mbc {

namespace {

bool stopsOrEnds(double m) {
  return m == 0 || m == 1 || m == 2 || m == 30;
}

} // namespace

// A FANUC code mbc does not execute may call a macro: the builder gave its
// number to the macro, and mbc relies only on the codes it executes.
bool mayBeCustomGCode(int tenths) {
  return !isFanucGCode(tenths) || unmodelledGCode(tenths) != nullptr;
}

bool mayBeCustomMCode(double m) {
  return !stopsOrEnds(m) && m != 98 && m != 99 && m != 198;
}

bool gCodeMayCall(int tenths, bool modalCalls) {
  return mayBeCustomGCode(tenths) ||
         (modalCalls && (tenths == 660 || tenths == 661));
}

bool mCodeMayCall(double m) {
  return !stopsOrEnds(m);
}

} // namespace mbc

// --trace of the statements the interpreter runs itself.
#include "frontend/trace_text.h"
#include "interp/interpreter.h"

namespace mbc {

void Interpreter::trace(const Stmt& s, std::initializer_list<mbrt_num> values,
                        bool taken) {
  const std::string tmpl = traceTemplate(unit_.programs[prog_], s, taken);
  mbrt_trace_values(ctx_, tmpl.c_str(), values.begin(), values.size());
}

} // namespace mbc

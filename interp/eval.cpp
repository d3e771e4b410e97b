// Expression evaluation through the shared arithmetic (mbc/arith.h), so the
// interpreter computes exactly what folding and compiled code compute.
#include "interp/interpreter.h"

namespace mbc {

mbrt_status Interpreter::check(AlarmId id) {
  return id == AlarmId::None ? 0
                             : mbrt_raise(ctx_, static_cast<int>(id), nullptr);
}

// roundLetter != 0: the expression is the value of that NC address, where
// ROUND rounds to the address's least increment (mbrt_round_address, spec
// §3.4); it does not reach into a variable number #[...].
mbrt_status Interpreter::eval(const Expr& e, Num& out, char roundLetter) {
  switch (e.kind) {
    case ExprKind::Number:
      out = e.number;
      return 0;
    case ExprKind::Var:
      return mbrt_read_var(ctx_, e.var, &out);
    case ExprKind::Indirect: {
      Num idx;
      if (mbrt_status st = eval(*e.args[0], idx)) {
        return st;
      }
      return mbrt_read_var(ctx_, numeric(idx), &out);
    }
    case ExprKind::Neg: {
      Num v;
      if (mbrt_status st = eval(*e.args[0], v, roundLetter)) {
        return st;
      }
      out = negate(v);
      return 0;
    }
    case ExprKind::Binary: {
      Num a, b;
      if (mbrt_status st = eval(*e.args[0], a, roundLetter)) {
        return st;
      }
      if (mbrt_status st = eval(*e.args[1], b, roundLetter)) {
        return st;
      }
      return check(evalBinary(e.binOp, a, b, &out));
    }
    case ExprKind::Call:
      return evalCall(e, out, roundLetter);
    case ExprKind::Parameter: {
      // n, then the bit and the axis that are written, as vacant-is-0
      // numbers.
      double values[3] = {0.0, 0.0, 0.0};
      for (std::size_t i = 0; i < e.args.size() && i < 3; ++i) {
        Num v;
        if (mbrt_status st = eval(*e.args[i], v)) {
          return st;
        }
        values[i] = numeric(v);
      }
      const bool bit = (e.parameterForm & MBRT_PARAMETER_BIT) != 0;
      const bool axis = (e.parameterForm & MBRT_PARAMETER_AXIS) != 0;
      return mbrt_read_parameter(ctx_, e.parameterForm, values[0],
                                 bit ? values[1] : 0.0,
                                 axis ? values[bit ? 2 : 1] : 0.0, &out);
    }
    case ExprKind::Compare:
    case ExprKind::Logical:
      break;
  }
  return check(AlarmId::IllegalExpressionFormat);
}

mbrt_status Interpreter::evalCall(const Expr& e, Num& out, char roundLetter) {
  if (e.builtin == Builtin::Adp) {
    const Expr& arg = *e.args[0];
    if (arg.isBareVariable()) {
      double number = arg.var;
      if (arg.kind == ExprKind::Indirect) {
        Num idx;
        if (mbrt_status st = eval(*arg.args[0], idx)) {
          return st;
        }
        number = numeric(idx);
      }
      return mbrt_adp(ctx_, number, &out);
    }
  }
  Num args[2] = {0, 0};
  for (std::size_t i = 0; i < e.args.size() && i < 2; ++i) {
    if (mbrt_status st = eval(*e.args[i], args[i], roundLetter)) {
      return st;
    }
  }
  if (e.builtin == Builtin::Round && roundLetter != 0) {
    return mbrt_round_address(ctx_, roundLetter, args[0], &out);
  }
  return mbrt_builtin(ctx_, static_cast<int>(e.builtin), args[0], args[1],
                      &out);
}

mbrt_status Interpreter::evalCond(const Expr& e, bool& out) {
  if (e.kind == ExprKind::Compare) {
    Num a, b;
    if (mbrt_status st = eval(*e.args[0], a)) {
      return st;
    }
    if (mbrt_status st = eval(*e.args[1], b)) {
      return st;
    }
    // Only a bare reference is vacant (spec §2.3): `[#1] EQ #0` is 0 EQ #0.
    if (!e.args[0]->isBareVariable()) {
      a = numeric(a);
    }
    if (!e.args[1]->isBareVariable()) {
      b = numeric(b);
    }
    out = evalCompare(e.relOp, a, b);
    return 0;
  }
  if (e.kind != ExprKind::Logical) {
    return check(AlarmId::IllegalExpressionFormat);
  }
  bool a = false, b = false;
  if (mbrt_status st = evalCond(*e.args[0], a)) {
    return st;
  }
  if (mbrt_status st = evalCond(*e.args[1], b)) {
    return st;
  }
  switch (e.binOp) {
    case BinOp::And:
      out = a && b;
      break;
    case BinOp::Or:
      out = a || b;
      break;
    default:
      out = a != b;
      break;
  }
  return 0;
}

} // namespace mbc

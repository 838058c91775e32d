// The engine's side of a parsed script: registers and name binding.
#include "runtime/script/program.hpp"

namespace uabt::runtime::script {

Program Program::parse(std::string_view code) {
  return of(Script::parse(code));
}

Program Program::of(Script script) {
  Program program;
  program.script_ = std::move(script);
  const std::vector<Expr>& nodes = program.script_.nodes();
  program.registers_.resize(nodes.size());
  // The literals true and false evaluate to the doubles 1.0 and 0.0 (BT.CPP's parsePrefix);
  // the parsed tree keeps them boolean for the readers that interpret it.
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const Expr& e = nodes[i];
    if (e.op == Op::literal && e.literal.kind == ScriptValue::Kind::boolean)
      program.registers_[i] = ScriptValue::of_real(e.literal.boolean ? 1.0 : 0.0);
  }
  return program;
}

void Program::bind(Blackboard& blackboard, ScopeId scope) {
  for (Expr& e : script_.nodes())
    if (e.op == Op::name) e.slot = blackboard.resolve(scope, e.name);
}

}  // namespace uabt::runtime::script

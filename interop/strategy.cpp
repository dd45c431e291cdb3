// boreas interop: strategy names and the automatic choice (strategy.h).
#include "strategy.h"

namespace boreas::interop {

const char* strategy_name(Strategy s) {
  switch (s) {
    case Strategy::gl_sharing: return "gl_sharing";
    case Strategy::zero_copy: return "zero_copy";
    case Strategy::copy: return "copy";
  }
  return "?";
}

std::optional<Strategy> parse_strategy(const std::string& name) {
  for (Strategy s : {Strategy::gl_sharing, Strategy::zero_copy, Strategy::copy})
    if (name == strategy_name(s)) return s;
  return std::nullopt;
}

Strategy choose_strategy(const InteropSupport& support) {
  if (support.context_shares_gl) return Strategy::gl_sharing;
  // A CPU device writes host memory anyway: let it write GL's. A discrete GPU without
  // sharing would read the host pointer over the bus on every access, so it copies once.
  if (support.device_is_cpu) return Strategy::zero_copy;
  return Strategy::copy;
}

}  // namespace boreas::interop

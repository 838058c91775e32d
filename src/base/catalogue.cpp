#include "base/catalogue.hpp"

namespace uabt {

const CheckInfo* find_check(const std::string& id) {
  for (const auto& info : check_catalogue())
    if (id == info.id) return &info;
  return nullptr;
}

}  // namespace uabt

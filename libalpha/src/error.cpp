#include "alpha/error.hpp"

namespace alpha {

void fail(const std::string& message) { throw Error(message); }

}  // namespace alpha

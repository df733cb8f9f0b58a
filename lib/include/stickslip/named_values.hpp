// Numbers a user assigns by name, in the order given: a run file's set and guess tables, --set
// and --guess on the command line, the columns of a stored point. Later entries win.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace stickslip {

using NamedValues = std::vector<std::pair<std::string, double>>;

}  // namespace stickslip

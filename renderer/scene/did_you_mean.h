// Name suggestion (host): the "did you mean 'X'?" hint for a misspelt block, parameter, material or texture.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace trazo {

// "did you mean 'X'?" for the candidate closest to `wrong` by edit distance, or "" when none is close.
std::string didYouMean(std::string_view wrong, const std::vector<std::string_view>& candidates);

}  // namespace trazo

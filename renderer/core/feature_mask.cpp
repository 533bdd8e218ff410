// describeFeatures (host): a feature mask in words, from the feature list (core/feature_mask.h).
#include "core/feature_mask.h"

namespace trazo {

std::string describeFeatures(FeatureMask mask) {
    std::string s;
    for (const FeatureName& f : kFeatureNames) {
        if (!(mask & f.bit)) continue;
        if (!s.empty()) s += ' ';
        s += f.name;
    }
    return s.empty() ? "none" : s;
}

}  // namespace trazo

// Parameter values back to scene-language text (host): what the scene writer prints on a parameter line, and
// the tables' default texts.
#pragma once

#include <string>

#include "scene/param_check.h"

namespace trazo {

// %.9g: every float reads back to the same bits.
std::string formatReal(float v);

// The values of one line as the reader reads them back to `value`: numbers (Real with formatReal), a name,
// or a path in double quotes relative to the folder of `scenePath` (absolute when on another root).
std::string formatValues(const ParamInfo& info, const ParamValue& value, const std::string& scenePath);

}  // namespace trazo

// trazo --render: scene file -> host scene -> device arrays -> backend passes -> image file.
#pragma once

#include "command_line.h"

namespace trazo {

// Returns the process exit status: 0 success, 1 runtime failure, 2 bad scene.
int runHeadlessRender(const CommandLine& options);

}  // namespace trazo

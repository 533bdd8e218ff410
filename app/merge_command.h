// trazo merge: partial renders (--partial) into one image, its stats and error estimate, or a partial again.
#pragma once

#include "command_line.h"

namespace trazo {

// Returns the exit status: 0 merged (with --allow-gaps, also when passes are missing), 2 parts that cannot be
// merged (unreadable, corrupt, different fingerprints, passes twice or missing) or a bad output name, 1 when
// an output cannot be written. Nothing is written unless the merge succeeds.
int runMerge(const MergeCommandLine& options);

}  // namespace trazo

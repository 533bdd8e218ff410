// The Render panel's numbers (panels.h's RenderInfo) read from the session and the display: backend, display
// path, size, passes, speed, flatten's warnings, the convergence series.
#pragma once

#include "model/viewer_session.h"
#include "view/display.h"
#include "view/panels.h"

namespace trazo {

RenderInfo describeRender(ViewerSession& session, const Display& display, bool cudaBuilt);

}  // namespace trazo

// A one-line progress bar on stderr, shown only once a render has run for more than a second.
#pragma once

#include "render/progressive_render.h"

namespace trazo {

class ProgressBar {
public:
    ProgressBar(bool enabled, double timeLimitSeconds) : enabled_(enabled), timeLimit_(timeLimitSeconds) {}
    void update(const RenderProgress& p);
    void finish();  // ends the line if anything was drawn

private:
    bool enabled_;
    double timeLimit_;
    bool drawn_ = false;
};

}  // namespace trazo

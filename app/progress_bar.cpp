// Progress bar drawing: fraction of passes, or of the time budget when that ends the render first.
#include "progress_bar.h"

#include <algorithm>
#include <cstdio>

namespace trazo {

void ProgressBar::update(const RenderProgress& p) {
    if (!enabled_ || p.elapsedSeconds < 1.0) return;
    double fraction = double(p.passesDone) / p.passesTarget;
    if (timeLimit_ > 0.0) fraction = std::max(fraction, p.elapsedSeconds / timeLimit_);
    fraction = std::min(fraction, 1.0);
    constexpr int kWidth = 30;
    const int filled = int(fraction * kWidth);
    char bar[kWidth + 1];
    for (int i = 0; i < kWidth; ++i) bar[i] = i < filled ? '#' : '-';
    bar[kWidth] = '\0';
    const double eta = fraction > 0.0 ? p.elapsedSeconds * (1.0 / fraction - 1.0) : 0.0;
    std::fprintf(stderr, "\r[%s] %3d%%  %u passes  %.1f s  eta %.1f s ", bar, int(fraction * 100.0), p.passesDone,
                 p.elapsedSeconds, eta);
    std::fflush(stderr);
    drawn_ = true;
}

void ProgressBar::finish() {
    if (drawn_) std::fputc('\n', stderr);
    drawn_ = false;
}

}  // namespace trazo

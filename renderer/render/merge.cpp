// mergePartialFiles: headers, checks, then the sum in pass order.
#include "render/merge.h"

#include <algorithm>
#include <numeric>

namespace trazo {

void addAccumulation(std::vector<AccumPixel>& total, const std::vector<AccumPixel>& part) {
    for (size_t i = 0; i < total.size(); ++i) {
        AccumPixel& t = total[i];
        const AccumPixel& p = part[i];
        for (int c = 0; c < 3; ++c) {
            t.sum[c] += p.sum[c];
            t.sumB[c] += p.sumB[c];
        }
        t.count += p.count;
        t.countB += p.countB;
    }
}

double mergeRelativeBound(uint32_t passes) {
    const double u = 0x1p-53, g = (passes > 1 ? passes - 1 : 0) * u / (1.0 - (passes > 1 ? passes - 1 : 0) * u);
    return 2.0 * g / (1.0 - g);
}

bool mergePartialFiles(const std::vector<std::string>& paths, const MergeOptions& options, MergeResult& result,
                       std::string& error) {
    error.clear();
    if (paths.empty()) {
        error = "no partial files given";
        return false;
    }
    std::vector<PartialHeader> headers(paths.size());
    for (size_t i = 0; i < paths.size(); ++i) {
        std::string why;
        if (!readPartialHeader(paths[i], headers[i], why)) error += why + "\n";
    }
    if (!error.empty()) return error.pop_back(), false;

    // The order of the sum: by first pass (then by name, for the overlapping parts reported below).
    std::vector<size_t> order(paths.size());
    std::iota(order.begin(), order.end(), size_t(0));
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
        const uint32_t fa = headers[a].passes.front().first, fb = headers[b].passes.front().first;
        return fa != fb ? fa < fb : paths[a] < paths[b];
    });
    const size_t first = order.front();
    for (size_t i : order) {
        const std::string difference = fingerprintDifference(headers[first].fingerprint, headers[i].fingerprint);
        if (!difference.empty())
            error += paths[i] + ": cannot be merged with " + paths[first] + ": they differ in " + difference + "\n";
    }
    if (!error.empty()) return error.pop_back(), false;

    std::vector<PassRange> covered;
    uint32_t lastAsked = 0;
    for (size_t a = 0; a < order.size(); ++a) {
        const PartialHeader& ha = headers[order[a]];
        for (const PassRange& r : ha.passes) covered.push_back(r);
        lastAsked = std::max({lastAsked, ha.requested.end, ha.passes.back().end});
        for (size_t b = a + 1; b < order.size(); ++b)
            for (const PassRange& ra : ha.passes)
                for (const PassRange& rb : headers[order[b]].passes)
                    if (const PassRange both = intersect(ra, rb); both.count() > 0)
                        error += "passes " + formatRange(both) + " are in both " + paths[order[a]] + " (" +
                                 formatRanges(ha.passes) + ") and " + paths[order[b]] + " (" +
                                 formatRanges(headers[order[b]].passes) + ")\n";
    }
    const PassRange target = options.expected.value_or(PassRange{0, lastAsked});
    covered = joinRanges(covered);
    for (const PassRange& r : covered)
        if (intersect(r, target) != r)
            error += "passes " + formatRanges(missingRanges(r, {target})) + " lie outside the passes asked for (" +
                     formatRange(target) + ")\n";
    result.missing = missingRanges(target, covered);
    if (!options.allowGaps)
        for (const PassRange& r : result.missing)
            error += "passes " + formatRange(r) + " are missing\n";
    if (!error.empty()) return error.pop_back(), false;

    PartialHeader& merged = result.header;
    merged = PartialHeader{};
    merged.fingerprint = headers[first].fingerprint;
    merged.passes = covered;
    merged.requested = target;
    merged.parts = 0;
    std::vector<std::string> backends;
    for (size_t i : order) {
        merged.parts += headers[i].parts;
        merged.rays += headers[i].rays;
        merged.seconds += headers[i].seconds;
        if (std::find(backends.begin(), backends.end(), headers[i].backend) == backends.end())
            backends.push_back(headers[i].backend);
    }
    std::sort(backends.begin(), backends.end());
    for (const std::string& b : backends) merged.backend += (merged.backend.empty() ? "" : "; ") + b;

    const Fingerprint& f = merged.fingerprint;
    result.accum.assign((size_t)f.width * f.height, AccumPixel{});
    std::vector<AccumPixel> part;
    for (size_t i : order) {
        PartialHeader again;
        if (!readPartialFile(paths[i], again, part, error)) return false;
        if (fingerprintDifference(again.fingerprint, headers[i].fingerprint) != "" || again.passes != headers[i].passes) {
            error = paths[i] + ": changed while it was being merged";
            return false;
        }
        addAccumulation(result.accum, part);
    }
    return true;
}

}  // namespace trazo

// Formatting of diagnostics as FILE:LINE[:COLUMN]: severity: reason (hint).
#include "scene/diagnostic.h"

#include <cstdio>

namespace trazo {

std::string formatDiagnostic(const Diagnostic& d) {
    std::string s = d.where.file;
    if (d.where.line > 0) {
        s += ':';
        s += std::to_string(d.where.line);
        if (d.where.column > 0) {
            s += ':';
            s += std::to_string(d.where.column);
        }
    }
    s += d.severity == Severity::Error ? ": error: " : ": warning: ";
    s += d.message;
    if (!d.hint.empty()) s += " (" + d.hint + ")";
    return s;
}

void printDiagnostics(const Diagnostics& diags) {
    for (const Diagnostic& d : diags.items) std::fprintf(stderr, "%s\n", formatDiagnostic(d).c_str());
}

}  // namespace trazo

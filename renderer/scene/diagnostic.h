// Diagnostic: one user-facing problem with a scene, CSG or OBJ file, reported as FILE:LINE: reason.
#pragma once

#include <string>
#include <vector>

namespace trazo {

enum class Severity { Warning, Error };

struct SourceLocation {
    std::string file;  // path as the user (or the naming file) wrote it, resolved relative to the scene
    int line = 0;      // 1-based; 0 when the problem concerns the whole file
    int column = 0;    // 1-based; 0 when not useful
};

struct Diagnostic {
    Severity severity = Severity::Error;
    SourceLocation where;
    std::string message;  // plain reason, no trailing period
    std::string hint;     // optional, e.g. "did you mean 'Radius'?"
};

// "file:line:column: error: message (hint)" — the form printed on stderr.
std::string formatDiagnostic(const Diagnostic& d);

struct Diagnostics {
    std::vector<Diagnostic> items;

    void error(SourceLocation where, std::string message, std::string hint = {}) {
        items.push_back({Severity::Error, std::move(where), std::move(message), std::move(hint)});
    }
    void warning(SourceLocation where, std::string message, std::string hint = {}) {
        items.push_back({Severity::Warning, std::move(where), std::move(message), std::move(hint)});
    }
    bool hasErrors() const {
        for (const auto& d : items)
            if (d.severity == Severity::Error) return true;
        return false;
    }
};

// Every item, formatted, one per line on stderr.
void printDiagnostics(const Diagnostics& diags);

}  // namespace trazo

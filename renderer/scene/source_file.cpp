// readSourceFile(): readWholeFile with its failure reported as a Diagnostic.
#include "scene/source_file.h"

#include "io/text_file.h"

namespace trazo {

std::optional<std::string> readSourceFile(const std::string& path, const char* kind, size_t maxBytes,
                                          Diagnostics& diags) {
    std::string text, reason;
    if (readWholeFile(path, text, reason, maxBytes)) return text;
    diags.error({path, 0, 0}, std::string("cannot read ") + kind + " file: " + reason);
    return std::nullopt;
}

}  // namespace trazo

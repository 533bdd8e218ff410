// Whole files (host): read in one piece (regular files only, of a bounded size), text written all or nothing
// (replaceAtomically), and the paths one file names relative to itself.
#pragma once

#include <cstddef>
#include <string>

namespace trazo {

// The most a reader takes in (SPEC §2, "Limits"): any text file read whole (OBJ meshes), and scene and CSG
// files, which are written by hand or by tools and are far smaller (10^4 objects take about 2 MB).
inline constexpr size_t kMaxTextFileBytes = size_t(1) << 30;   // 1 GiB
inline constexpr size_t kMaxSceneFileBytes = size_t(64) << 20;  // 64 MiB

// Opens `path` read-only if it is a regular file, refusing anything else before opening it (a FIFO blocks an
// open for ever, /dev/zero never ends, a folder opens but does not read). The descriptor, or -1 with a plain
// reason: strerror's words ("No such file or directory", "Is a directory") or "not a regular file (a FIFO)".
int openRegularFile(const std::string& path, std::string& reason);

// The whole file in `contents`, read straight into a string of the file's size (no stream buffer copies:
// a mesh can be tens of MB). False with a plain reason (as openRegularFile's, or "file too large (N bytes;
// the limit is M)" when it holds more than `maxBytes`, checked before anything is allocated).
bool readWholeFile(const std::string& path, std::string& contents, std::string& reason,
                   size_t maxBytes = kMaxTextFileBytes);

// `written` relative to the folder of `namingFile` (unchanged when absolute), lexically normalised.
std::string resolveRelativePath(const std::string& namingFile, const std::string& written);

// Writes `text` to `path` through replaceAtomically; false with a plain reason in `error` when the file cannot
// be written or replaced.
bool writeTextFileAtomically(const std::string& path, const std::string& text, std::string& error);

}  // namespace trazo

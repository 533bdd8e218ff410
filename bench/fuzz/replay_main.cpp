// The fuzz harnesses' main() where libFuzzer is not linked (GCC, the normal build): runs every file named
// (or in every folder named) through LLVMFuzzerTestOneInput, then, for --seconds, deterministic mutations of
// them (bit flips, interesting bytes, insertions, deletions, line splices and swaps, extreme numbers,
// cross-overs, truncation). Same seed, same sequence. A crash (signal or abort) writes the input that caused
// it to <artifact-prefix>crash-<n> before the process dies, so it can be replayed:
// An input that runs past --timeout seconds (default 10) is written and the process aborts likewise.
//   trazo_fuzz_scene <corpus-folder-or-file>... [--seconds S] [--seed N] [--max-len BYTES] [--timeout S]
//                    [--artifact-prefix P]
#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <fcntl.h>
#include <unistd.h>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

namespace {

using Bytes = std::vector<uint8_t>;

// The input being run, for the crash handler (written with write(2) only).
const Bytes* gCurrent = nullptr;
char gCrashPath[4096];

void onCrash(int sig) {
    if (sig == SIGALRM) {
        const char msg[] = "\ntrazo fuzz replay: an input ran past --timeout\n";
        (void)!::write(2, msg, sizeof msg - 1);
    }
    if (gCurrent) {
        const int fd = ::open(gCrashPath, O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (fd >= 0) {
            size_t done = 0;
            while (done < gCurrent->size()) {
                const ssize_t n = ::write(fd, gCurrent->data() + done, gCurrent->size() - done);
                if (n <= 0) break;
                done += size_t(n);
            }
            ::close(fd);
            const char msg[] = "\ntrazo fuzz replay: crashing input written to ";
            (void)!::write(2, msg, sizeof msg - 1);
            (void)!::write(2, gCrashPath, std::strlen(gCrashPath));
            (void)!::write(2, "\n", 1);
        }
    }
    if (sig == SIGALRM) sig = SIGABRT;  // a hang is a finding: die as a crash does
    std::signal(sig, SIG_DFL);
    std::raise(sig);
}

struct Rng {
    uint64_t state;
    uint64_t next() {  // splitmix64
        uint64_t z = (state += 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return z ^ (z >> 31);
    }
    size_t below(size_t n) { return n ? size_t(next() % n) : 0; }
};

const char* const kExtremeNumbers[] = {
    "0", "-0", "1", "-1", "1e30", "-1e30", "1e-30", "1e38", "3.5e38", "-3.5e38", "1e309", "nan", "-nan",
    "inf", "-inf", "65536", "65535", "4294967295", "4294967296", "2147483647", "-2147483648",
    "9223372036854775807", "-9223372036854775808", "18446744073709551616", "0x10", "1e", ".", "-", "+",
    "00000000000000000000000000001", "16384", "32768", "1048577", "100000",
};
const char* const kTokens[] = {"{", "}", "\"", "\n", "\r", "\r\n", "#", " ", "\t", "/", "//", "f ", "v ",
                               "vt ", "vn ", "Source \"", "Name ", "Material ", "\\", "..", "/dev/zero"};
const uint8_t kInterestingBytes[] = {0, 0xff, 0x7f, 0x80, '\n', '\r', '{', '}', '"', '-', '.', ' ', '0', '9'};

bool isNumberByte(uint8_t c) { return (c >= '0' && c <= '9') || c == '.' || c == '-' || c == '+' || c == 'e'; }

// [begin, end) of the line holding `pos`, the newline excluded.
void lineAround(const Bytes& b, size_t pos, size_t& begin, size_t& end) {
    begin = pos;
    while (begin > 0 && b[begin - 1] != '\n') --begin;
    end = pos;
    while (end < b.size() && b[end] != '\n') ++end;
}

void insertText(Bytes& b, size_t pos, const std::string& s) { b.insert(b.begin() + long(pos), s.begin(), s.end()); }

void mutateOnce(Bytes& b, const std::vector<Bytes>& corpus, Rng& rng, size_t maxLen) {
    const size_t pos = rng.below(b.size() + 1);
    switch (rng.below(12)) {
        case 0:  // bit flip
            if (!b.empty()) b[rng.below(b.size())] ^= uint8_t(1u << rng.below(8));
            break;
        case 1:  // interesting byte
            if (!b.empty()) b[rng.below(b.size())] = kInterestingBytes[rng.below(sizeof kInterestingBytes)];
            break;
        case 2: {  // random bytes inserted
            const size_t n = 1 + rng.below(8);
            for (size_t i = 0; i < n; ++i) b.insert(b.begin() + long(pos), uint8_t(rng.next()));
            break;
        }
        case 3: {  // a range deleted
            if (b.empty()) break;
            const size_t start = rng.below(b.size());
            const size_t n = 1 + rng.below(std::min<size_t>(b.size() - start, 64));
            b.erase(b.begin() + long(start), b.begin() + long(start + n));
            break;
        }
        case 4:
        case 5: {  // a number replaced with an extreme one
            if (b.empty()) break;
            size_t at = rng.below(b.size());
            size_t tries = 0;
            while (tries < b.size() && !isNumberByte(b[at])) at = (at + 1) % b.size(), ++tries;
            size_t s = at, e = at;
            while (s > 0 && isNumberByte(b[s - 1])) --s;
            while (e < b.size() && isNumberByte(b[e])) ++e;
            const std::string n = kExtremeNumbers[rng.below(std::size(kExtremeNumbers))];
            b.erase(b.begin() + long(s), b.begin() + long(e));
            insertText(b, s, n);
            break;
        }
        case 6:  // a token inserted
            insertText(b, pos, kTokens[rng.below(std::size(kTokens))]);
            break;
        case 7: {  // a line deleted
            if (b.empty()) break;
            size_t s, e;
            lineAround(b, rng.below(b.size()), s, e);
            b.erase(b.begin() + long(s), b.begin() + long(std::min(e + 1, b.size())));
            break;
        }
        case 8: {  // a line duplicated elsewhere (from this input or another)
            const Bytes& from = corpus.empty() || rng.below(2) ? b : corpus[rng.below(corpus.size())];
            if (from.empty()) break;
            size_t s, e;
            lineAround(from, rng.below(from.size()), s, e);
            Bytes line(from.begin() + long(s), from.begin() + long(std::min(e + 1, from.size())));
            size_t at = rng.below(b.size() + 1), ls, le;
            if (at < b.size()) lineAround(b, at, ls, le), at = ls;
            b.insert(b.begin() + long(at), line.begin(), line.end());
            break;
        }
        case 9: {  // two lines swapped
            if (b.empty()) break;
            size_t s1, e1, s2, e2;
            lineAround(b, rng.below(b.size()), s1, e1);
            lineAround(b, rng.below(b.size()), s2, e2);
            if (s1 > s2) std::swap(s1, s2), std::swap(e1, e2);
            if (e1 >= s2) break;
            Bytes out(b.begin(), b.begin() + long(s1));
            out.insert(out.end(), b.begin() + long(s2), b.begin() + long(e2));
            out.insert(out.end(), b.begin() + long(e1), b.begin() + long(s2));
            out.insert(out.end(), b.begin() + long(s1), b.begin() + long(e1));
            out.insert(out.end(), b.begin() + long(e2), b.end());
            b.swap(out);
            break;
        }
        case 10: {  // cross-over: our head, another input's tail
            if (corpus.empty()) break;
            const Bytes& other = corpus[rng.below(corpus.size())];
            const size_t cut = rng.below(b.size() + 1), from = rng.below(other.size() + 1);
            b.resize(cut);
            b.insert(b.end(), other.begin() + long(from), other.end());
            break;
        }
        case 11:  // truncation, or a long run of one byte
            if (rng.below(2)) {
                b.resize(rng.below(b.size() + 1));
            } else {
                b.insert(b.begin() + long(pos), 1 + rng.below(4096), kInterestingBytes[rng.below(sizeof kInterestingBytes)]);
            }
            break;
    }
    if (b.size() > maxLen) b.resize(maxLen);
}

bool readFile(const std::filesystem::path& p, Bytes& out) {
    std::ifstream in(p, std::ios::binary);
    if (!in) return false;
    out.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    return true;
}

int usage(const char* argv0) {
    std::fprintf(stderr,
                 "usage: %s <corpus-folder-or-file>... [--seconds S] [--seed N] [--max-len BYTES] "
                 "[--timeout S] [--artifact-prefix PREFIX]\n"
                 "Runs every input once, then deterministic mutations of them for S seconds (default 0).\n",
                 argv0);
    return 2;
}

}  // namespace

int main(int argc, char** argv) {
    double seconds = 0;
    uint64_t seed = 1;
    size_t maxLen = 256 * 1024;
    unsigned timeout = 10;
    std::string prefix = "./";
    std::vector<std::filesystem::path> inputs;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&]() -> const char* { return i + 1 < argc ? argv[++i] : nullptr; };
        if (a == "--seconds" || a == "--seed" || a == "--max-len" || a == "--artifact-prefix" ||
            a == "--timeout") {
            const char* v = value();
            if (!v) return usage(argv[0]);
            if (a == "--seconds") seconds = std::atof(v);
            else if (a == "--seed") seed = std::strtoull(v, nullptr, 10);
            else if (a == "--max-len") maxLen = std::strtoull(v, nullptr, 10);
            else if (a == "--timeout") timeout = unsigned(std::strtoul(v, nullptr, 10));
            else prefix = v;
        } else if (a == "-h" || a == "--help" || (!a.empty() && a[0] == '-')) {
            return usage(argv[0]);
        } else {
            inputs.emplace_back(a);
        }
    }
    if (inputs.empty()) return usage(argv[0]);

    std::vector<Bytes> corpus;
    std::vector<std::string> names;
    for (const auto& p : inputs) {
        std::error_code ec;
        if (std::filesystem::is_directory(p, ec)) {
            std::vector<std::filesystem::path> files;
            for (const auto& e : std::filesystem::directory_iterator(p, ec))
                if (e.is_regular_file(ec)) files.push_back(e.path());
            std::sort(files.begin(), files.end());
            for (const auto& f : files) {
                Bytes b;
                if (readFile(f, b)) corpus.push_back(std::move(b)), names.push_back(f.string());
            }
        } else {
            Bytes b;
            if (!readFile(p, b)) {
                std::fprintf(stderr, "%s: cannot read %s\n", argv[0], p.string().c_str());
                return 2;
            }
            corpus.push_back(std::move(b));
            names.push_back(p.string());
        }
    }
    if (corpus.empty()) {
        std::fprintf(stderr, "%s: no inputs found\n", argv[0]);
        return 2;
    }

    for (int sig : {SIGSEGV, SIGABRT, SIGFPE, SIGBUS, SIGILL, SIGALRM}) std::signal(sig, onCrash);
    unsigned long crashNumber = 0;
    auto setCrashPath = [&]() {
        std::snprintf(gCrashPath, sizeof gCrashPath, "%scrash-%lu", prefix.c_str(), crashNumber);
    };
    setCrashPath();

    const auto t0 = std::chrono::steady_clock::now();
    for (size_t i = 0; i < corpus.size(); ++i) {
        gCurrent = &corpus[i];
        std::snprintf(gCrashPath, sizeof gCrashPath, "%scrash-seed-%zu", prefix.c_str(), i);
        ::alarm(timeout);
        LLVMFuzzerTestOneInput(corpus[i].data(), corpus[i].size());
        ::alarm(0);
    }
    gCurrent = nullptr;
    std::fprintf(stderr, "%s: %zu corpus inputs ran\n", argv[0], corpus.size());

    Rng rng{seed};
    uint64_t runs = 0;
    Bytes input;
    auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };
    while (seconds > 0 && elapsed() < seconds) {
        input = corpus[rng.below(corpus.size())];
        const size_t steps = 1 + rng.below(4);
        for (size_t s = 0; s < steps; ++s) mutateOnce(input, corpus, rng, maxLen);
        crashNumber = (unsigned long)runs;
        setCrashPath();
        gCurrent = &input;
        ::alarm(timeout);
        LLVMFuzzerTestOneInput(input.data(), input.size());
        ::alarm(0);
        gCurrent = nullptr;
        ++runs;
    }
    const double t = elapsed();
    std::fprintf(stderr, "%s: %llu mutated inputs in %.1f s (%.0f exec/s), seed %llu, no crash\n", argv[0],
                 (unsigned long long)runs, t, t > 0 ? double(runs) / t : 0.0, (unsigned long long)seed);
    return 0;
}

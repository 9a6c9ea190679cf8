// A small mutational fuzzer (AFL-style havoc) that drives LLVMFuzzerTestOneInput where libFuzzer
// is not available (GCC builds; docs/fuzzing.md). Usage: fuzz_driver CORPUS_DIR SECONDS [SEED].
// Each round takes a corpus entry and applies 1 to 8 random edits (flip a bit, set a byte,
// insert or delete a run, duplicate a run, splice in part of another entry, insert a token that
// parsers find interesting). A crash leaves the input that caused it in crash-<n> in the working
// directory and ends the process by the same signal; the test then fails.
#include "scene_loader_fuzz.h"
#include "util/clock.h"

#include <fcntl.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

namespace {

using Bytes = std::vector<uint8_t>;

// The input being run, for the crash handler (plain storage: it must not allocate).
Bytes g_current;

void on_crash(int sig) {
    char name[32];
    std::snprintf(name, sizeof name, "crash-%d", int(getpid()));
    const int fd = ::open(name, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) {
        (void)!::write(fd, g_current.data(), g_current.size());
        ::close(fd);
    }
    const char msg[] = "fuzz_driver: crashed; the input is in crash-<pid>\n";
    (void)!::write(STDERR_FILENO, msg, sizeof msg - 1);
    std::signal(sig, SIG_DFL);
    std::raise(sig);
}

const char* const kTokens[] = {"1e30",
                               "-1e30",
                               "3e38",
                               "1e999",
                               "nan",
                               "inf",
                               "-0",
                               "0",
                               "-1",
                               "4294967296",
                               "18446744073709551615",
                               "0x10",
                               "\"",
                               "{",
                               "}",
                               "[",
                               "]",
                               ",",
                               ":",
                               "\\u0000",
                               "\xEF\xBB\xBF",
                               "\n",
                               "f ",
                               "v ",
                               "vt ",
                               "vn ",
                               "usemtl ",
                               "mtllib ",
                               "newmtl ",
                               "illum 7",
                               "Ni ",
                               "map_Kd ",
                               "/",
                               "//",
                               "1/1/1",
                               "-3",
                               "\"type\": \"sphere\"",
                               "\"subdivisions\": ",
                               "\"translate\": ",
                               "\"rotate\": ",
                               "\"scale\": ",
                               "\"axis\": [0, 0, 0]",
                               "\"objects\": []",
                               "\"bufferView\": 0",
                               "\"byteOffset\": ",
                               "\"byteStride\": ",
                               "\"count\": ",
                               "\"componentType\": 5121",
                               "\"normalized\": true",
                               "\"mode\": 5",
                               "\"children\": [0]",
                               "\"matrix\": [0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1]",
                               "\"rotation\": [0, 0, 0, 1]",
                               "\"scale\": [0, 0, 0]",
                               "\"texCoord\": 1",
                               "\"sparse\": {\"count\": 1, \"indices\": {\"bufferView\": 0, "
                               "\"componentType\": 5121}, \"values\": {\"bufferView\": 0}}",
                               "data:application/octet-stream;base64,",
                               "NaN",
                               "glTF"};

Bytes mutate(const std::vector<Bytes>& corpus, std::mt19937_64& rng) {
    auto pick = [&](size_t n) { return n == 0 ? size_t(0) : size_t(rng() % n); };
    Bytes b = corpus[pick(corpus.size())];
    const int edits = 1 + int(pick(8));
    for (int e = 0; e < edits; ++e) {
        // Edits keep byte 0 (the input's kind) unless they replace the whole input.
        const size_t at = b.size() > 1 ? 1 + pick(b.size() - 1) : b.size();
        switch (pick(7)) {
        case 0:
            if (at < b.size()) b[at] ^= uint8_t(1u << pick(8));
            break;
        case 1:
            if (at < b.size()) b[at] = uint8_t(rng());
            break;
        case 2:
            b.insert(b.begin() + long(at), 1 + pick(8), uint8_t(rng()));
            break;
        case 3:
            if (at < b.size())
                b.erase(b.begin() + long(at),
                        b.begin() + long(std::min(b.size(), at + 1 + pick(16))));
            break;
        case 4:
            if (at < b.size()) {
                const Bytes run(b.begin() + long(at),
                                b.begin() + long(std::min(b.size(), at + 1 + pick(64))));
                b.insert(b.begin() + long(pick(b.size()) + (b.size() > 1 ? 1 : 0)), run.begin(),
                         run.end());
            }
            break;
        case 5: {
            const Bytes& other = corpus[pick(corpus.size())];
            if (other.size() > 1) {
                const size_t from = 1 + pick(other.size() - 1);
                const size_t n = 1 + pick(std::min<size_t>(other.size() - from, 256));
                b.insert(b.begin() + long(at), other.begin() + long(from),
                         other.begin() + long(from + n));
            }
            break;
        }
        default: {
            const std::string t = kTokens[pick(std::size(kTokens))];
            b.insert(b.begin() + long(at), t.begin(), t.end());
        }
        }
    }
    return b;
}

} // namespace

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(stderr, "usage: %s CORPUS_DIR SECONDS [SEED]\n", argv[0]);
        return 2;
    }
    std::vector<Bytes> corpus;
    for (const auto& f : std::filesystem::directory_iterator(argv[1])) {
        std::ifstream in(f.path(), std::ios::binary);
        corpus.emplace_back(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    if (corpus.empty()) {
        std::fprintf(stderr, "fuzz_driver: %s holds no inputs\n", argv[1]);
        return 2;
    }
    const double seconds = std::atof(argv[2]);
    std::mt19937_64 rng(argc > 3 ? std::strtoull(argv[3], nullptr, 10) : 1);
    for (int sig : {SIGSEGV, SIGABRT, SIGBUS, SIGFPE, SIGILL}) std::signal(sig, on_crash);
    g_current.reserve(1 << 20);

    const auto t0 = std::chrono::steady_clock::now();
    uint64_t runs = 0;
    for (const Bytes& b : corpus) {
        g_current = b;
        LLVMFuzzerTestOneInput(g_current.data(), g_current.size());
        ++runs;
    }
    while (tp::seconds_since(t0) < seconds) {
        g_current = mutate(corpus, rng);
        LLVMFuzzerTestOneInput(g_current.data(), g_current.size());
        ++runs;
    }
    std::printf("fuzz_driver: %llu inputs in %.0f s, no crash\n", (unsigned long long)runs,
                seconds);
    return 0;
}

// What the batch means of a Sobol render would add to the lean film (docs/sampling.md, "What
// the file keeps"): reads a `render --film full` EXR and prints the bytes of a second EXR part
// holding them, written in memory next to a first part with the lean film's channels (R, G, B,
// variance.*, sample_variance.* rounded to 11 significant bits), as the size of the two-part
// file less that of the first part alone. A measuring tool, not product code; the command is in
// README.md.
#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfMultiPartOutputFile.h>
#include <OpenEXR/ImfOutputPart.h>
#include <OpenEXR/ImfPartType.h>
#include <OpenEXR/ImfStdIO.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

namespace {

using Plane = std::vector<float>;

struct Image {
    int width = 0, height = 0;
    std::map<std::string, Plane> channels;
};

Image read(const char* path) {
    Imf::InputFile file(path);
    const Imath::Box2i dw = file.header().dataWindow();
    Image img;
    img.width = dw.max.x - dw.min.x + 1;
    img.height = dw.max.y - dw.min.y + 1;
    Imf::FrameBuffer fb;
    for (auto it = file.header().channels().begin(); it != file.header().channels().end(); ++it) {
        Plane& p = img.channels[it.name()];
        p.resize(size_t(img.width) * size_t(img.height));
        fb.insert(it.name(), Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(p.data()),
                                        sizeof(float), sizeof(float) * size_t(img.width)));
    }
    file.setFrameBuffer(fb);
    file.readPixels(dw.min.y, dw.max.y);
    return img;
}

// One channel to write: float32 or half.
struct Channel {
    std::string name;
    Plane values;
    bool half = false;
};
using Part = std::vector<Channel>;

// Bytes of a ZIP-compressed scanline file of the given parts, written in memory.
size_t file_bytes(int width, int height, const std::vector<Part>& parts) {
    std::vector<Imf::Header> headers;
    for (size_t i = 0; i < parts.size(); ++i) {
        Imf::Header h(width, height);
        h.compression() = Imf::ZIP_COMPRESSION;
        h.setName(i == 0 ? "image" : "batches");
        h.setType(Imf::SCANLINEIMAGE);
        for (const Channel& c : parts[i])
            h.channels().insert(c.name, Imf::Channel(c.half ? Imf::HALF : Imf::FLOAT));
        headers.push_back(h);
    }
    Imf::StdOSStream os;
    Imf::MultiPartOutputFile out(os, headers.data(), int(headers.size()));
    std::vector<std::vector<half>> halves; // alive until writePixels
    for (size_t i = 0; i < parts.size(); ++i) {
        Imf::OutputPart part(out, int(i));
        Imf::FrameBuffer fb;
        for (const Channel& c : parts[i]) {
            if (c.half) {
                halves.emplace_back(c.values.begin(), c.values.end());
                fb.insert(c.name,
                          Imf::Slice(Imf::HALF, reinterpret_cast<char*>(halves.back().data()),
                                     sizeof(half), sizeof(half) * size_t(width)));
            } else {
                fb.insert(c.name, Imf::Slice(Imf::FLOAT,
                                             const_cast<char*>(
                                                 reinterpret_cast<const char*>(c.values.data())),
                                             sizeof(float), sizeof(float) * size_t(width)));
            }
        }
        part.setFrameBuffer(fb);
        part.writePixels(height);
    }
    return os.str().size();
}

// x rounded to nearest with `bits` significant bits (as render/film.h's lean_sample_variance).
float round_significant(float x, int bits) {
    if (!std::isfinite(x) || x == 0.0f) return x;
    int e = 0;
    const double m = std::frexp(double(x), &e);
    return float(std::ldexp(std::nearbyint(std::ldexp(m, bits)), e - bits));
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: batch_part_sizes FULL.exr (a render --film full)\n");
        return 2;
    }
    Image img = read(argv[1]);
    const int K = 8;
    const char* colour[3] = {"R", "G", "B"};
    Part lean;
    for (const char* prefix : {"", "variance.", "sample_variance."})
        for (const char* c : colour) {
            Channel ch{std::string(prefix) + c, img.channels.at(std::string(prefix) + c)};
            if (std::string(prefix) == "sample_variance.")
                for (float& v : ch.values) v = round_significant(v, 11);
            lean.push_back(ch);
        }
    const size_t lean_bytes = file_bytes(img.width, img.height, {lean});
    std::printf("lean film alone: %zu bytes\n", lean_bytes);

    // The batch means as deviations from the mean in units of one batch's standard deviation
    // (sqrt(K variance of the mean)), so that half precision's exponent range is never at issue.
    auto deviation = [&](int b, const char* c) {
        const Plane& m = img.channels.at(c);
        const Plane& v = img.channels.at(std::string("variance.") + c);
        const Plane& mb = img.channels.at("batch" + std::to_string(b) + "." + c);
        Plane d(m.size());
        for (size_t i = 0; i < m.size(); ++i) {
            const double sd = std::sqrt(K * double(v[i]));
            d[i] = sd > 0 ? float((double(mb[i]) - m[i]) / sd) : 0.0f;
        }
        return d;
    };
    auto report = [&](const char* what, const Part& batches) {
        const size_t both = file_bytes(img.width, img.height, {lean, batches});
        std::printf("%s: %zu bytes\n", what, both - lean_bytes);
    };
    for (int batches : {8, 7})
        for (int bits : {11, 5, 3}) {
            Part part;
            for (const char* c : colour)
                for (int b = 0; b < batches; ++b) {
                    Plane d = deviation(b, c);
                    for (float& x : d) x = round_significant(x, bits);
                    part.push_back({"batch" + std::to_string(b) + "." + c, d, true});
                }
            char what[96];
            std::snprintf(what, sizeof what, "%d x 3 half deviations, %d significant bits", batches,
                          bits);
            report(what, part);
        }
    Part means;
    for (const char* c : colour)
        for (int b = 0; b < K; ++b) {
            const std::string name = "batch" + std::to_string(b) + "." + c;
            means.push_back({name, img.channels.at(name), true});
        }
    report("8 x 3 batch means in half precision", means);
    return 0;
}

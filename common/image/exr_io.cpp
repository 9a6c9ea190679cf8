#include "image/exr_io.h"

#include "util/error.h"
#include "util/output_file.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfDoubleAttribute.h>
#include <OpenEXR/ImfFloatAttribute.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStdIO.h>
#include <OpenEXR/ImfStringAttribute.h>

#include <cstdio>
#include <filesystem>

namespace tp {

const std::vector<float>& ExrImage::channel(const std::string& name) const {
    auto it = channels.find(name);
    if (it == channels.end()) input_error("image has no channel '{}'", name);
    return it->second;
}

void write_exr(const std::string& path, const ExrImage& image) {
    // Encoded in memory, then written by write_output_file (util/output_file.h).
    Imf::StdOSStream encoded;
    try {
        Imf::Header header(image.width, image.height);
        header.compression() = Imf::ZIP_COMPRESSION;
        for (const auto& [name, data] : image.channels) {
            if (data.size() != size_t(image.width) * size_t(image.height))
                runtime_error("{}: channel {} has {} values for {}x{} pixels", path, name,
                              data.size(), image.width, image.height);
            header.channels().insert(name, Imf::Channel(Imf::FLOAT));
        }
        // Attributes every header has (pixelAspectRatio, screenWindowWidth, ...) are set by
        // the Header constructor with their own types; read_exr returns them too, so they are
        // skipped here rather than re-inserted with a different type, which OpenEXR rejects.
        const Imf::Header standard(image.width, image.height);
        auto own = [&](const std::string& k) { return standard.find(k) == standard.end(); };
        for (const auto& [k, v] : image.strings)
            if (own(k)) header.insert(k, Imf::StringAttribute(v));
        for (const auto& [k, v] : image.integers)
            if (own(k)) header.insert(k, Imf::IntAttribute(int(v)));
        for (const auto& [k, v] : image.reals)
            if (own(k)) header.insert(k, Imf::DoubleAttribute(v));
        Imf::OutputFile file(encoded, header);
        Imf::FrameBuffer fb;
        for (const auto& [name, data] : image.channels)
            fb.insert(name, Imf::Slice(Imf::FLOAT, (char*)data.data(), sizeof(float),
                                       sizeof(float) * size_t(image.width)));
        file.setFrameBuffer(fb);
        file.writePixels(image.height);
    } catch (const RuntimeError&) {
        throw;
    } catch (const std::exception& e) {
        runtime_error("cannot write {}: {}", path, e.what());
    }
    write_output_file(path, encoded.str());
}

ExrImage read_exr(const std::string& path) {
    if (!std::filesystem::exists(path)) input_error("{}: no such file", path);
    ExrImage image;
    try {
        Imf::InputFile file(path.c_str());
        const Imf::Header& header = file.header();
        const Imath::Box2i dw = header.dataWindow();
        image.width = dw.max.x - dw.min.x + 1;
        image.height = dw.max.y - dw.min.y + 1;
        const size_t n = size_t(image.width) * size_t(image.height);
        Imf::FrameBuffer fb;
        for (auto it = header.channels().begin(); it != header.channels().end(); ++it) {
            auto& data = image.channels[it.name()];
            data.resize(n);
            // The slice base is offset so that data window pixel (min.x, min.y) lands at 0.
            char* base =
                (char*)data.data() - (ptrdiff_t(dw.min.x) + ptrdiff_t(dw.min.y) * image.width) *
                                         ptrdiff_t(sizeof(float));
            fb.insert(it.name(), Imf::Slice(Imf::FLOAT, base, sizeof(float),
                                            sizeof(float) * size_t(image.width)));
        }
        file.setFrameBuffer(fb);
        file.readPixels(dw.min.y, dw.max.y);
        for (auto it = header.begin(); it != header.end(); ++it) {
            const Imf::Attribute& a = it.attribute();
            if (auto* s = dynamic_cast<const Imf::StringAttribute*>(&a))
                image.strings[it.name()] = s->value();
            else if (auto* i = dynamic_cast<const Imf::IntAttribute*>(&a))
                image.integers[it.name()] = i->value();
            else if (auto* d = dynamic_cast<const Imf::DoubleAttribute*>(&a))
                image.reals[it.name()] = d->value();
            else if (auto* f = dynamic_cast<const Imf::FloatAttribute*>(&a))
                image.reals[it.name()] = f->value();
        }
    } catch (const std::exception& e) {
        input_error("{}: not a readable OpenEXR image: {}", path, e.what());
    }
    return image;
}

} // namespace tp

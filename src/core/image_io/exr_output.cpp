// EXR files through OpenEXR, written as OpenImageIO's EXR writer writes them (see
// direct_image_output.h for why not through it): one scanline part, every channel 32-bit
// float, ZIP compression in blocks of 16 lines, the time of writing as `capDate`. Attributes
// keep their names and types, but for two that OpenImageIO names for every format:
// `ImageDescription` is EXR's standard `comments`, and `oiio:` ones (the colour space) are
// OpenImageIO's own and not written, the file being linear by EXR's definition.

#include <algorithm>
#include <ctime>
#include <exception>
#include <mutex>
#include <string>
#include <thread>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFloatAttribute.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfThreading.h>

#include "core/image_io/direct_image_output.h"

namespace wt {

namespace {

// "YYYY:MM:DD HH:MM:SS", local time: the form the EXR standard gives capDate.
std::string capture_date() {
    const std::time_t now = std::time(nullptr);
    std::tm local{};
    char text[32] = "";
    if (localtime_r(&now, &local)) std::strftime(text, sizeof text, "%Y:%m:%d %H:%M:%S", &local);
    return text;
}

// OpenEXR compresses blocks of lines on its global thread pool, which has no thread until it
// is given some: one thread would deflate a large image while the other cores, done rendering,
// wait. OpenImageIO gives the pool a thread per core; so do we.
int compression_threads() {
    static std::once_flag once;
    std::call_once(once, [] { Imf::setGlobalThreadCount(int(std::max(1u, std::thread::hardware_concurrency()))); });
    return Imf::globalThreadCount();
}

void add_attributes(const WtImageToWrite& image, Imf::Header& header) {
    for (int i = 0; i < image.attribute_count; ++i) {
        const WtImageAttribute& a = image.attributes[i];
        const std::string name = a.name;
        if (name.rfind("oiio:", 0) == 0) continue;
        if (name == "ImageDescription" && a.type == WT_ATTRIBUTE_STRING) {
            Imf::addComments(header, a.string_value);
        } else if (a.type == WT_ATTRIBUTE_INT) {
            header.insert(name, Imf::IntAttribute(a.int_value));
        } else if (a.type == WT_ATTRIBUTE_FLOAT) {
            header.insert(name, Imf::FloatAttribute(a.float_value));
        } else {
            header.insert(name, Imf::StringAttribute(a.string_value));
        }
    }
    const std::string date = capture_date();
    if (!date.empty()) Imf::addCapDate(header, date);
}

}  // namespace

void write_exr(const WtImageToWrite& image) {
    const std::string path = image.path;
    if (image.pixel_type != WT_PIXEL_FLOAT)
        throw ImageError(path + ": EXR files are written from float pixels");
    try {
        Imf::Header header(image.width, image.height);
        header.compression() = Imf::ZIP_COMPRESSION;
        add_attributes(image, header);
        const auto* pixels = static_cast<const char*>(image.pixels);
        const std::size_t pixel_stride = sizeof(float) * std::size_t(image.channels);
        const std::size_t row_stride = pixel_stride * std::size_t(image.width);
        Imf::FrameBuffer frame;
        for (int c = 0; c < image.channels; ++c) {
            header.channels().insert(image.channel_names[c], Imf::Channel(Imf::FLOAT));
            // The slice's base is where pixel (0, 0) of this channel would be: the data window
            // starts at the origin, so that is the first pixel's value.
            frame.insert(image.channel_names[c],
                         Imf::Slice(Imf::FLOAT, const_cast<char*>(pixels) + sizeof(float) * std::size_t(c), pixel_stride,
                                    row_stride));
        }
        Imf::OutputFile file(path.c_str(), header, compression_threads());
        file.setFrameBuffer(frame);
        file.writePixels(image.height);
    } catch (const std::exception& e) {
        throw ImageError(path + ": writing failed: " + e.what());
    }
}

}  // namespace wt

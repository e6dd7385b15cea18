// OpenEXR reading and writing through the OpenEXR 3 library. Files are read
// from memory and written through an AtomicFile, so this module, not OpenEXR,
// owns every file access: one open per call, one error style, atomic replace.
#include "image/exr_detail.h"
#include "image/file_util.h"
#include "image/image_io.h"

#include <Iex.h>
#include <half.h>
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfVersion.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <limits>
#include <map>
#include <set>

namespace dvsgi::image {

using detail::fail;

namespace {

// A corrupt header can claim any data window, and OpenEXR sizes its buffers
// from it; 2^28 pixels (16k x 16k) is far beyond any frame this project makes.
constexpr uint64_t kMaxPixels = uint64_t(1) << 28;
// The same guard for the raw bytes of all channels together (many channels
// make a big buffer from a modest window).
constexpr uint64_t kMaxRawBytes = uint64_t(1) << 32;

// The most pixel bytes one byte of a file can hold with each compression, with
// margin: zlib (ZIP, ZIPS) expands at most 1032:1, PXR24 is zlib on 24 of
// every 32 bits, an RLE run gives 128 bytes for 2, B44A a flat 4x4 block 32
// bytes for 3 (B44: 14), PIZ's run-length code 512 bytes for about 11 bits,
// and DWA adds zlib on top of 64:1 DCT blocks. A header can then not claim
// more pixels than its data holds: a 300-byte file claimed a 2^28-pixel
// window and made the reader allocate and clear 4 GB (found by fuzz_exr).
uint64_t maxExpansion(Imf::Compression c) {
    switch (c) {
        case Imf::NO_COMPRESSION: return 1;
        case Imf::RLE_COMPRESSION: return 64;
        case Imf::ZIPS_COMPRESSION:
        case Imf::ZIP_COMPRESSION: return 1100;
        case Imf::PXR24_COMPRESSION: return 1500;
        case Imf::B44_COMPRESSION: return 3;
        case Imf::B44A_COMPRESSION: return 11;
        case Imf::PIZ_COMPRESSION: return 400;
        default: return 70000;  // DWAA, DWAB
    }
}

// IoError messages are one line starting with the path; OpenEXR's may span
// lines and quote the path again ('... image file "<path>". ...').
std::string libraryMessage(const std::string& path, std::string s) {
    const std::string quoted = " \"" + path + "\"";
    for (size_t at; (at = s.find(quoted)) != std::string::npos;) s.erase(at, quoted.size());
    std::replace(s.begin(), s.end(), '\n', ' ');
    std::replace(s.begin(), s.end(), '\r', ' ');
    return s;
}

// The whole file in memory: its size bounds every read, so a truncated file is
// an exception here, never a read past the end.
class MemoryIStream final : public Imf::IStream {
public:
    MemoryIStream(const std::string& path, std::vector<uint8_t>& bytes)
        : Imf::IStream(path.c_str()), data_(reinterpret_cast<char*>(bytes.data())),
          size_(bytes.size()) {}

    bool isMemoryMapped() const override { return true; }
    bool read(char c[], int n) override {
        std::memcpy(c, take(n), size_t(n));
        return pos_ < size_;
    }
    char* readMemoryMapped(int n) override { return take(n); }
    uint64_t tellg() override { return pos_; }
    // A seek past the end is only an error once something is read there.
    void seekg(uint64_t pos) override { pos_ = pos; }

    const uint8_t* bytes() const { return reinterpret_cast<const uint8_t*>(data_); }
    uint64_t size() const { return size_; }

private:
    char* take(int n) {
        if (n < 0 || pos_ > size_ || uint64_t(n) > size_ - pos_)
            throw Iex::InputExc("unexpected end of file (truncated file?)");
        char* p = data_ + pos_;
        pos_ += uint64_t(n);
        return p;
    }

    char* data_;
    uint64_t size_;
    uint64_t pos_ = 0;
};

// Writes into an AtomicFile. OpenEXR writes its offset table from a destructor
// that swallows exceptions, so failures are also remembered for the caller.
class FileOStream final : public Imf::OStream {
public:
    FileOStream(const std::string& path, std::FILE* f) : Imf::OStream(path.c_str()), f_(f) {}

    void write(const char c[], int n) override {
        if (std::fwrite(c, 1, size_t(n), f_) != size_t(n)) failed(errno);
    }
    uint64_t tellp() override {
        const off_t pos = ::ftello(f_);
        if (pos < 0) failed(errno);
        return uint64_t(pos);
    }
    void seekp(uint64_t pos) override {
        if (::fseeko(f_, off_t(pos), SEEK_SET) != 0) failed(errno);
    }

    int error() const { return error_; }

private:
    [[noreturn]] void failed(int err) {
        if (!error_) error_ = err ? err : EIO;
        fail(fileName(), std::string("write failed: ") + std::strerror(error_));
    }

    std::FILE* f_;
    int error_ = 0;
};

uint32_t readLe32(const uint8_t* p) {
    return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
}

std::string sizeText(int64_t w, int64_t h) { return std::to_string(w) + "x" + std::to_string(h); }

// Attribute types whose value OpenEXR 3.1 reads as a fixed number of bytes,
// whatever the attribute's size field says.
struct FixedType {
    const char* name;
    uint32_t bytes;
};
constexpr FixedType kFixedTypes[] = {
    {"box2i", 16}, {"box2f", 16}, {"compression", 1}, {"chromaticities", 32}, {"deepImageState", 1},
    {"double", 8}, {"envmap", 1}, {"float", 4}, {"int", 4}, {"keycode", 28}, {"lineOrder", 1},
    {"m33f", 36}, {"m33d", 72}, {"m44f", 64}, {"m44d", 128}, {"rational", 8}, {"tiledesc", 9},
    {"timecode", 8}, {"v2i", 8}, {"v2f", 8}, {"v2d", 16}, {"v3i", 12}, {"v3f", 12}, {"v3d", 24}};

// OpenEXR reads names of up to 255 bytes plus the NUL.
constexpr uint64_t kMaxNameBytes = 256;

std::string printable(const std::string& s) {
    std::string out;
    for (unsigned char c : s.substr(0, 64)) out += std::isprint(c) ? char(c) : '?';
    return out;
}

// Fails unless OpenEXR 3.1 reads exactly `size` bytes for this value. Then its
// read position and the size fields agree attribute by attribute, and every
// buffer it sizes from a value (strings, vectors, preview, unknown types) is
// bounded by bytes the file really has.
void checkAttributeValue(const std::string& path, const std::string& name, const std::string& type,
                         const uint8_t* v, uint64_t size) {
    auto bad = [&](const std::string& why) {
        fail(path, "corrupt header (attribute '" + printable(name) + "' of type '" + printable(type) + "': " + why + ")");
    };
    for (const FixedType& f : kFixedTypes)
        if (type == f.name) {
            if (size != f.bytes)
                bad("size " + std::to_string(size) + ", the type has " + std::to_string(f.bytes) + " bytes");
            return;
        }
    if (type == "chlist") {
        // Channels (name, then 16 bytes) up to an empty name; OpenEXR reads
        // them to that end whatever the size says.
        uint64_t at = 0;
        for (;;) {
            const void* nul = std::memchr(v + at, 0, std::min(size - at, kMaxNameBytes));
            if (!nul) bad("channel list without its end within the attribute");
            const uint64_t length = uint64_t(static_cast<const uint8_t*>(nul) - (v + at));
            at += length + 1;
            if (length == 0) break;
            if (size - at < 16) bad("channel list without its end within the attribute");
            at += 16;
        }
        if (at != size) bad("channel list of " + std::to_string(at) + " bytes, size " + std::to_string(size));
    } else if (type == "stringvector") {
        for (uint64_t at = 0; at < size;) {
            if (size - at < 4) bad("string vector cut short");
            const int32_t n = int32_t(readLe32(v + at));
            at += 4;
            if (n < 0 || uint64_t(n) > size - at)
                bad("string of " + std::to_string(n) + " bytes in a value of " + std::to_string(size));
            at += uint64_t(n);
        }
    } else if (type == "floatvector") {
        if (size % 4) bad("size " + std::to_string(size) + " is not a whole number of floats");
    } else if (type == "preview") {
        if (size < 8) bad("size " + std::to_string(size) + " is shorter than the preview's header");
        const uint64_t w = readLe32(v), h = readLe32(v + 4);
        if (8 + 4 * w * h != size)
            bad("preview " + sizeText(int64_t(w), int64_t(h)) + " does not fill its size " + std::to_string(size));
    } else if (type == "idmanifest") {
        if (size < 8) bad("size " + std::to_string(size) + " is shorter than the manifest's header");
    }
    // "string" and types OpenEXR does not know read exactly `size` bytes.
}

// Walks one header's attribute list (name, type, int32 size, value) from
// `at`. OpenEXR allocates many values from their size before reading them: a
// 119-byte file whose attribute of unknown type claimed 1.75 GB made it
// allocate (and ASan clear) 1.75 GB (found by fuzz_exr).
void checkAttributeSizes(const std::string& path, const MemoryIStream& in, uint64_t at) {
    const uint8_t* bytes = in.bytes();
    const uint64_t size = in.size();
    // A name from `at`; false where OpenEXR's own read fails (no NUL in reach).
    auto readName = [&](uint64_t& pos, std::string& out) -> bool {
        const void* nul = pos < size ? std::memchr(bytes + pos, 0, std::min(size - pos, kMaxNameBytes)) : nullptr;
        if (!nul) return false;
        const uint64_t end = uint64_t(static_cast<const uint8_t*>(nul) - bytes);
        out.assign(reinterpret_cast<const char*>(bytes + pos), end - pos);
        pos = end + 1;
        return true;
    };
    std::string name, type;
    for (;;) {
        if (!readName(at, name) || name.empty()) return;  // the empty name ends the header
        if (!readName(at, type) || size - at < 4) return;
        const int32_t claimed = int32_t(readLe32(bytes + at));
        at += 4;
        if (claimed < 0 || uint64_t(claimed) > size - at)
            fail(path, "corrupt header (attribute '" + printable(name) + "' claims " + std::to_string(claimed) +
                           " bytes, " + std::to_string(size - at) + " remain in the file)");
        checkAttributeValue(path, name, type, bytes + at, uint64_t(claimed));
        at += uint64_t(claimed);
    }
}

// Reads the header(s) alone and rejects sizes no real file of ours has, before
// OpenEXR allocates line buffers, offset tables or tiles from them.
void checkHeaders(const std::string& path, MemoryIStream& in) {
    if (in.size() < 8) fail(path, "not an OpenEXR file (only " + std::to_string(in.size()) + " bytes)");
    if (!Imf::isImfMagic(reinterpret_cast<const char*>(in.bytes())))
        fail(path, "not an OpenEXR file (bad magic number)");
    int version = int(readLe32(in.bytes() + 4));
    if (Imf::getVersion(version) != Imf::EXR_VERSION)
        fail(path, "unsupported OpenEXR version " + std::to_string(Imf::getVersion(version)));
    if (!Imf::supportsFlags(Imf::getFlags(version))) fail(path, "unknown OpenEXR version flags");
    if (version & Imf::NON_IMAGE_FLAG) fail(path, "deep OpenEXR files are not supported");
    const bool multiPart = (version & Imf::MULTI_PART_FILE_FLAG) != 0;

    in.seekg(8);
    for (;;) {
        checkAttributeSizes(path, in, in.tellg());
        Imf::Header header;
        header.readFrom(in, version);
        const Imath::Box2i dw = header.dataWindow();
        const int64_t w = int64_t(dw.max.x) - dw.min.x + 1, h = int64_t(dw.max.y) - dw.min.y + 1;
        if (w <= 0 || h <= 0) fail(path, "corrupt header (empty data window " + sizeText(w, h) + ")");
        const uint64_t pixels = uint64_t(w) * uint64_t(h);
        if (pixels > kMaxPixels)
            fail(path, "data window " + sizeText(w, h) + " is too large (limit 2^28 pixels)");
        uint64_t bytesPerPixel = 0;
        for (auto it = header.channels().begin(); it != header.channels().end(); ++it)
            bytesPerPixel += it.channel().type == Imf::HALF ? 2 : 4;
        if (pixels * bytesPerPixel > kMaxRawBytes)
            fail(path, "data window " + sizeText(w, h) + " with " + std::to_string(bytesPerPixel) +
                           " bytes per pixel is too large (limit 4 GiB)");
        if (pixels * bytesPerPixel > in.size() * maxExpansion(header.compression()))
            fail(path, "data window " + sizeText(w, h) + " needs " + std::to_string(pixels * bytesPerPixel) +
                           " bytes of pixels, more than a " + std::to_string(in.size()) +
                           "-byte file holds with its compression");
        if (header.hasTileDescription()) {
            const Imf::TileDescription& t = header.tileDescription();
            if (uint64_t(t.xSize) * t.ySize > kMaxPixels)
                fail(path, "tile size " + sizeText(t.xSize, t.ySize) + " is too large");
        }
        // A multi-part file ends its list of headers with an empty one.
        if (!multiPart || in.tellg() >= in.size() || in.bytes()[in.tellg()] == 0) break;
    }
    in.seekg(0);
}

// Opens the file for reading after the header checks; the caller catches.
struct ExrInput {
    std::vector<uint8_t> bytes;
    MemoryIStream stream;
    Imf::InputFile file;

    // The comma runs checkHeaders before InputFile's constructor, which is
    // where OpenEXR first sizes buffers from the header.
    ExrInput(const std::string& path, std::vector<uint8_t> data)
        : bytes(std::move(data)), stream(path, bytes),
          file((checkHeaders(path, stream), stream)) {
        // A file cut short has a partial chunk table; reading it would fail
        // chunk by chunk after the image is allocated.
        if (!file.isComplete()) fail(path, "truncated file (pixel data missing)");
    }
};

// Turns any library exception into one IoError line naming the file.
template <typename Fn>
auto wrapErrors(const std::string& path, Fn&& fn) -> decltype(fn()) {
    try {
        return fn();
    } catch (const IoError&) {
        throw;
    } catch (const std::exception& e) {
        fail(path, libraryMessage(path, e.what()));
    }
}

// One float source per file channel; `base` points at pixel (0,0) of a
// tightly packed width x height image.
struct ChannelSource {
    std::string name;
    const float* base;
    size_t xStride;  // bytes
};

void checkDimensions(const std::string& path, uint32_t width, uint32_t height) {
    if (width == 0 || height == 0)
        fail(path, "cannot write an empty image (" + sizeText(width, height) + ")");
    if (width > uint32_t(std::numeric_limits<int32_t>::max()) ||
        height > uint32_t(std::numeric_limits<int32_t>::max()))
        fail(path, "image " + sizeText(width, height) + " is too large for OpenEXR");
}

void writeChannels(const std::string& path, uint32_t width, uint32_t height,
                   const std::vector<ChannelSource>& channels, PixelType type) {
    const bool half = type == PixelType::Half;
    const size_t pixels = size_t(width) * height;
    wrapErrors(path, [&] {
        Imf::Header header{int(width), int(height)};
        header.compression() = Imf::ZIP_COMPRESSION;
        Imf::FrameBuffer frame;
        // OpenEXR writes a slice only in its channel's own type, so half
        // channels get converted copies, one plane per channel.
        std::vector<Imath::half> halves(half ? channels.size() * pixels : 0);
        for (size_t i = 0; i < channels.size(); ++i) {
            const ChannelSource& c = channels[i];
            if (half) {
                Imath::half* plane = halves.data() + i * pixels;
                const char* src = reinterpret_cast<const char*>(c.base);
                for (size_t p = 0; p < pixels; ++p)
                    plane[p] = Imath::half(*reinterpret_cast<const float*>(src + p * c.xStride));
                header.channels().insert(c.name, Imf::Channel(Imf::HALF));
                frame.insert(c.name, Imf::Slice(Imf::HALF, reinterpret_cast<char*>(plane),
                                                sizeof(Imath::half), sizeof(Imath::half) * width));
            } else {
                header.channels().insert(c.name, Imf::Channel(Imf::FLOAT));
                frame.insert(c.name, Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(const_cast<float*>(c.base)),
                                                c.xStride, c.xStride * width));
            }
        }
        detail::AtomicFile out(path);
        FileOStream stream(path, out.file());
        {
            Imf::OutputFile file(stream, header);
            file.setFrameBuffer(frame);
            file.writePixels(int(height));
        }
        if (stream.error()) fail(path, std::string("write failed: ") + std::strerror(stream.error()));
        out.commit();
    });
}

// Channel order within a layer as readers list them: colour, then vectors.
int channelRank(const std::string& c) {
    static const char* order[] = {"R", "G", "B", "A", "X", "Y", "Z"};
    for (int i = 0; i < int(std::size(order)); ++i)
        if (c == order[i]) return i;
    return int(std::size(order));
}

}  // namespace

void writeExr(const std::string& path, const ImageRGBA32F& img) { writeExr(path, img, ExrOptions{}); }

void writeExr(const std::string& path, const ImageRGBA32F& img, const ExrOptions& options) {
    checkDimensions(path, img.width, img.height);
    if (img.rgba.size() != img.pixelCount() * 4)
        fail(path, "image has " + std::to_string(img.rgba.size()) + " floats, expected " +
                       std::to_string(img.pixelCount() * 4));
    std::vector<ChannelSource> channels;
    const char* names[] = {"R", "G", "B", "A"};
    for (int c = 0; c < (options.alpha ? 4 : 3); ++c)
        channels.push_back({names[c], img.rgba.data() + c, 4 * sizeof(float)});
    writeChannels(path, img.width, img.height, channels, options.type);
}

ImageRGBA32F readExr(const std::string& path) { return detail::readExrBytes(path, detail::readFileBytes(path)); }

ImageRGBA32F detail::readExrBytes(const std::string& path, std::vector<uint8_t> bytes) {
    return wrapErrors(path, [&] {
        ExrInput in(path, std::move(bytes));
        const Imf::Header& header = in.file.header();
        for (const char* c : {"R", "G", "B"})
            if (!header.channels().findChannel(c))
                fail(path, std::string("no '") + c + "' channel (readExr needs R, G and B)");
        const Imath::Box2i dw = header.dataWindow();
        ImageRGBA32F img = ImageRGBA32F::blank(uint32_t(dw.max.x - dw.min.x + 1),
                                               uint32_t(dw.max.y - dw.min.y + 1));
        Imf::FrameBuffer frame;
        const char* names[] = {"R", "G", "B", "A"};
        for (int c = 0; c < 4; ++c)
            frame.insert(names[c], Imf::Slice::Make(Imf::FLOAT, img.rgba.data() + c, dw,
                                                    4 * sizeof(float), 4 * sizeof(float) * img.width,
                                                    1, 1, c == 3 ? 1.0 : 0.0));
        in.file.setFrameBuffer(frame);
        in.file.readPixels(dw.min.y, dw.max.y);
        return img;
    });
}

void writeExrLayers(const std::string& path, uint32_t width, uint32_t height,
                    const std::vector<ExrLayer>& layers, PixelType type) {
    checkDimensions(path, width, height);
    if (layers.empty()) fail(path, "no layers to write");
    std::vector<ChannelSource> channels;
    std::set<std::string> seen;
    for (const ExrLayer& layer : layers) {
        const std::string what = "layer '" + layer.name + "'";
        const size_t n = layer.channels.size();
        if (n != 1 && n != 3 && n != 4)
            fail(path, what + " has " + std::to_string(n) + " channels (1, 3 or 4 expected)");
        if (layer.pixels.size() != size_t(width) * height * n)
            fail(path, what + " has " + std::to_string(layer.pixels.size()) + " floats, expected " +
                           std::to_string(size_t(width) * height * n));
        for (size_t c = 0; c < n; ++c) {
            const std::string& ch = layer.channels[c];
            if (ch.empty() || ch.find('.') != std::string::npos)
                fail(path, what + " has channel name '" + ch + "' (must be non-empty, without '.')");
            const std::string full = layer.name.empty() ? ch : layer.name + "." + ch;
            if (!seen.insert(full).second) fail(path, "channel '" + full + "' is given twice");
            channels.push_back({full, layer.pixels.data() + c, n * sizeof(float)});
        }
    }
    writeChannels(path, width, height, channels, type);
}

ExrLayerFile readExrLayers(const std::string& path) {
    return detail::readExrLayersBytes(path, detail::readFileBytes(path));
}

ExrLayerFile detail::readExrLayersBytes(const std::string& path, std::vector<uint8_t> bytes) {
    return wrapErrors(path, [&] {
        ExrInput in(path, std::move(bytes));
        const Imf::Header& header = in.file.header();
        const Imath::Box2i dw = header.dataWindow();
        ExrLayerFile result;
        result.width = uint32_t(dw.max.x - dw.min.x + 1);
        result.height = uint32_t(dw.max.y - dw.min.y + 1);

        struct Found {
            std::vector<std::string> channels;
            Imf::PixelType type;
        };
        std::map<std::string, Found> byLayer;  // sorted by layer name
        for (auto it = header.channels().begin(); it != header.channels().end(); ++it) {
            const std::string full = it.name();
            const Imf::Channel& ch = it.channel();
            if (ch.xSampling != 1 || ch.ySampling != 1)
                fail(path, "channel '" + full + "' is subsampled, which is not supported");
            if (ch.type != Imf::HALF && ch.type != Imf::FLOAT)
                fail(path, "channel '" + full + "' has UINT samples; only HALF and FLOAT layers are read");
            const size_t dot = full.rfind('.');
            const std::string layer = dot == std::string::npos ? "" : full.substr(0, dot);
            auto [entry, added] = byLayer.try_emplace(layer, Found{{}, ch.type});
            if (!added && entry->second.type != ch.type)
                fail(path, "layer '" + layer + "' mixes HALF and FLOAT channels");
            entry->second.channels.push_back(dot == std::string::npos ? full : full.substr(dot + 1));
        }

        Imf::FrameBuffer frame;
        for (auto& [name, found] : byLayer) {
            std::sort(found.channels.begin(), found.channels.end(),
                      [](const std::string& a, const std::string& b) {
                          const int ra = channelRank(a), rb = channelRank(b);
                          return ra != rb ? ra < rb : a < b;
                      });
            ExrLayer& layer = result.layers.emplace_back();
            layer.name = name;
            layer.channels = found.channels;
            const size_t n = layer.channels.size();
            layer.pixels.assign(size_t(result.width) * result.height * n, 0.0f);
            result.types.push_back(found.type == Imf::HALF ? PixelType::Half : PixelType::Float);
            for (size_t c = 0; c < n; ++c)
                frame.insert(name.empty() ? layer.channels[c] : name + "." + layer.channels[c],
                             Imf::Slice::Make(Imf::FLOAT, layer.pixels.data() + c, dw,
                                              n * sizeof(float), n * sizeof(float) * result.width));
        }
        in.file.setFrameBuffer(frame);
        in.file.readPixels(dw.min.y, dw.max.y);
        return result;
    });
}

}  // namespace dvsgi::image

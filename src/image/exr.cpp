// Minimal OpenEXR 2.0 scanline reader/writer. Layout (all little-endian):
//   magic 76 2f 31 01 | version 2 + flags (int32) | attributes
//   (name\0 type\0 int32 size, value) ... \0 | offset table (uint64 per chunk)
//   | chunks (int32 first y, int32 data size, data).
// Inside a chunk the data is, per scanline, each channel's samples for the
// whole line, channels in header order.
#include "image/image_io.h"

#include "image/file_util.h"

#include <zlib.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>

namespace dvsgi::image {

using detail::fail;

namespace {

constexpr uint8_t kMagic[4] = {0x76, 0x2f, 0x31, 0x01};

// EXR header enums.
enum PixelType : int32_t { kUint = 0, kHalf = 1, kFloat = 2 };
enum Compression : uint8_t { kNone = 0, kRle = 1, kZips = 2, kZip = 3, kPiz = 4 };

// Guards the reader against absurd data windows in corrupt headers before it
// allocates; 2^28 pixels is far beyond any frame this project writes.
constexpr uint64_t kMaxPixels = uint64_t(1) << 28;

const char* compressionName(uint8_t c) {
    static const char* names[] = {"none", "RLE", "ZIPS", "ZIP", "PIZ", "PXR24",
                                  "B44",  "B44A", "DWAA", "DWAB"};
    return c < std::size(names) ? names[c] : "unknown";
}

// ---- byte-level helpers ---------------------------------------------------

void putU32(std::vector<uint8_t>& out, uint32_t v) {
    for (int i = 0; i < 4; ++i) out.push_back(uint8_t(v >> (8 * i)));
}
void putI32(std::vector<uint8_t>& out, int32_t v) { putU32(out, uint32_t(v)); }
void putU64At(std::vector<uint8_t>& out, size_t pos, uint64_t v) {
    for (int i = 0; i < 8; ++i) out[pos + i] = uint8_t(v >> (8 * i));
}
void putF32(std::vector<uint8_t>& out, float v) { putU32(out, std::bit_cast<uint32_t>(v)); }
void putStr(std::vector<uint8_t>& out, const char* s) {
    out.insert(out.end(), s, s + std::strlen(s) + 1);
}

uint32_t getU32(const uint8_t* p) {
    return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
}
int32_t getI32(const uint8_t* p) { return int32_t(getU32(p)); }
uint64_t getU64(const uint8_t* p) { return uint64_t(getU32(p)) | uint64_t(getU32(p + 4)) << 32; }

float halfToFloat(uint16_t h) {
    const uint32_t sign = uint32_t(h & 0x8000) << 16;
    const uint32_t exp = (h >> 10) & 0x1f;
    const uint32_t mant = h & 0x3ff;
    if (exp == 0) {  // zero or subnormal: mant * 2^-24, exact in float
        const float v = std::ldexp(float(mant), -24);
        return (h & 0x8000) ? -v : v;
    }
    if (exp == 31) return std::bit_cast<float>(sign | 0x7f800000u | (mant << 13));
    return std::bit_cast<float>(sign | ((exp + 112) << 23) | (mant << 13));
}

// ---- ZIP chunk coding -----------------------------------------------------
// OpenEXR's ZIP (and ZIPS) compressor first splits the bytes into even and odd
// halves (separating the high and low bytes of each sample improves zlib's
// matches) and then delta-codes them with a +128 bias, before deflating.

std::vector<uint8_t> zipEncode(const std::vector<uint8_t>& raw) {
    const size_t n = raw.size();
    std::vector<uint8_t> tmp(n);
    size_t half = (n + 1) / 2;
    for (size_t i = 0; i < n; ++i) tmp[(i & 1) ? half + i / 2 : i / 2] = raw[i];
    for (size_t i = n; i-- > 1;) tmp[i] = uint8_t(int(tmp[i]) - int(tmp[i - 1]) + 128);

    uLongf outLen = compressBound(uLong(n));
    std::vector<uint8_t> out(outLen);
    if (compress2(out.data(), &outLen, tmp.data(), uLong(n), Z_DEFAULT_COMPRESSION) != Z_OK)
        return {};  // caller stores the chunk raw
    out.resize(outLen);
    return out;
}

// Returns false if the stream is not exactly `rawSize` bytes of valid zlib data.
bool zipDecode(const uint8_t* src, size_t srcLen, std::vector<uint8_t>& raw, size_t rawSize) {
    std::vector<uint8_t> tmp(rawSize);
    uLongf outLen = uLongf(rawSize);
    if (uncompress(tmp.data(), &outLen, src, uLong(srcLen)) != Z_OK || outLen != rawSize)
        return false;
    for (size_t i = 1; i < rawSize; ++i) tmp[i] = uint8_t(int(tmp[i - 1]) + int(tmp[i]) - 128);
    raw.resize(rawSize);
    const size_t half = (rawSize + 1) / 2;
    for (size_t i = 0; i < rawSize; ++i) raw[i] = tmp[(i & 1) ? half + i / 2 : i / 2];
    return true;
}

// ---- header parsing -------------------------------------------------------

struct Channel {
    std::string name;
    int32_t type = kFloat;
    int target = -1;  // RGBA component it feeds, -1 = ignored
    size_t bytes() const { return type == kHalf ? 2 : 4; }
};

struct Header {
    std::vector<Channel> channels;
    bool hasChannels = false, hasCompression = false, hasDataWindow = false;
    uint8_t compression = kNone;
    int32_t xMin = 0, yMin = 0, xMax = -1, yMax = -1;
};

class Parser {
public:
    Parser(const std::string& path, const std::vector<uint8_t>& bytes)
        : path_(path), d_(bytes.data()), n_(bytes.size()) {}

    ImageRGBA32F parse() {
        if (n_ < 8) fail(path_, "not an OpenEXR file (only " + std::to_string(n_) + " bytes)");
        if (std::memcmp(d_, kMagic, 4) != 0) fail(path_, "not an OpenEXR file (bad magic number)");
        const uint32_t versionField = getU32(d_ + 4);
        if ((versionField & 0xff) != 2)
            fail(path_, "unsupported OpenEXR version " + std::to_string(versionField & 0xff));
        const uint32_t flags = versionField & ~0xffu;
        if (flags & 0x200) fail(path_, "tiled OpenEXR files are not supported");
        if (flags & 0x800) fail(path_, "deep OpenEXR files are not supported");
        if (flags & 0x1000) fail(path_, "multi-part OpenEXR files are not supported");
        if (flags & ~0x400u) fail(path_, "unknown OpenEXR version flags");
        pos_ = 8;
        Header h = parseHeader();
        return readPixels(h);
    }

private:
    [[noreturn]] void bad(const std::string& what) const { fail(path_, what); }

    void need(uint64_t bytes, const char* what) const {
        if (pos_ > n_ || bytes > n_ - pos_) bad(std::string("truncated file (") + what + ")");
    }

    std::string readName(const char* what) {
        // Names are at most 255 bytes (with the long-names flag; 31 without).
        const size_t start = pos_;
        while (pos_ < n_ && d_[pos_] != 0) {
            if (pos_ - start > 255) bad(std::string("corrupt header (") + what + " too long)");
            ++pos_;
        }
        if (pos_ >= n_) bad(std::string("truncated file (") + what + ")");
        std::string s(reinterpret_cast<const char*>(d_ + start), pos_ - start);
        ++pos_;
        return s;
    }

    Header parseHeader() {
        Header h;
        for (;;) {
            const std::string name = readName("attribute name");
            if (name.empty()) break;
            const std::string type = readName("attribute type");
            need(4, "attribute size");
            const int32_t size = getI32(d_ + pos_);
            pos_ += 4;
            if (size < 0) bad("corrupt header (attribute '" + name + "' has negative size)");
            need(uint64_t(size), "attribute value");
            const uint8_t* v = d_ + pos_;
            auto expect = [&](const char* t, int32_t s) {
                if (type != t || (s >= 0 && size != s))
                    bad("corrupt header (attribute '" + name + "' has type '" + type +
                        "' and size " + std::to_string(size) + ")");
            };
            if (name == "channels") {
                expect("chlist", -1);
                parseChannels(h, v, size_t(size));
            } else if (name == "compression") {
                expect("compression", 1);
                h.compression = v[0];
                h.hasCompression = true;
            } else if (name == "dataWindow") {
                expect("box2i", 16);
                h.xMin = getI32(v), h.yMin = getI32(v + 4);
                h.xMax = getI32(v + 8), h.yMax = getI32(v + 12);
                h.hasDataWindow = true;
            } else if (name == "type") {
                // Single-part files may still name their part type.
                const std::string t(reinterpret_cast<const char*>(v),
                                    strnlen(reinterpret_cast<const char*>(v), size_t(size)));
                if (t != "scanlineimage") bad("unsupported part type '" + t + "'");
            }
            pos_ += size_t(size);
        }
        if (!h.hasChannels) bad("missing required attribute 'channels'");
        if (!h.hasCompression) bad("missing required attribute 'compression'");
        if (!h.hasDataWindow) bad("missing required attribute 'dataWindow'");
        return h;
    }

    void parseChannels(Header& h, const uint8_t* v, size_t size) {
        size_t p = 0;
        for (;;) {
            const size_t start = p;
            while (p < size && v[p] != 0) ++p;
            if (p >= size) bad("corrupt header (unterminated channel list)");
            std::string name(reinterpret_cast<const char*>(v + start), p - start);
            ++p;
            if (name.empty()) break;
            if (size - p < 16) bad("corrupt header (channel '" + name + "' truncated)");
            Channel c;
            c.name = name;
            c.type = getI32(v + p);
            const int32_t xs = getI32(v + p + 8), ys = getI32(v + p + 12);
            p += 16;
            if (c.type != kUint && c.type != kHalf && c.type != kFloat)
                bad("channel '" + name + "' has unknown pixel type " + std::to_string(c.type));
            if (xs != 1 || ys != 1)
                bad("channel '" + name + "' is subsampled, which is not supported");
            static const char* rgba[] = {"R", "G", "B", "A"};
            for (int k = 0; k < 4; ++k)
                if (name == rgba[k]) c.target = k;
            h.channels.push_back(std::move(c));
        }
        for (const char* req : {"R", "G", "B"}) {
            bool found = false;
            for (const Channel& c : h.channels) found |= c.name == req;
            if (!found) bad(std::string("no '") + req + "' channel (only R, G, B[, A] images are supported)");
        }
        h.hasChannels = true;
    }

    ImageRGBA32F readPixels(const Header& h) {
        int linesPerChunk = 0;
        switch (h.compression) {
            case kNone: case kZips: linesPerChunk = 1; break;
            case kZip: linesPerChunk = 16; break;
            default:
                bad(std::string("unsupported compression ") + compressionName(h.compression) +
                    " (supported: none, ZIPS, ZIP)");
        }
        const int64_t w = int64_t(h.xMax) - h.xMin + 1, ht = int64_t(h.yMax) - h.yMin + 1;
        if (w <= 0 || ht <= 0) bad("corrupt header (empty data window)");
        if (uint64_t(w) * uint64_t(ht) > kMaxPixels)
            bad("data window " + std::to_string(w) + "x" + std::to_string(ht) + " is too large");

        size_t pixelBytes = 0;
        for (const Channel& c : h.channels) pixelBytes += c.bytes();
        const size_t lineBytes = pixelBytes * size_t(w);
        const int64_t chunks = (ht + linesPerChunk - 1) / linesPerChunk;

        need(uint64_t(chunks) * 8, "offset table");
        const size_t tablePos = pos_;

        ImageRGBA32F img = ImageRGBA32F::blank(uint32_t(w), uint32_t(ht));
        std::vector<bool> seen(size_t(chunks), false);
        std::vector<uint8_t> raw;
        for (int64_t i = 0; i < chunks; ++i) {
            const uint64_t off = getU64(d_ + tablePos + size_t(i) * 8);
            const std::string where = "chunk " + std::to_string(i);
            if (off > n_ || n_ - off < 8) bad(where + " lies outside the file (truncated file?)");
            const int32_t y = getI32(d_ + off);
            const int32_t size = getI32(d_ + off + 4);
            const int64_t rel = int64_t(y) - h.yMin;
            if (rel < 0 || rel >= ht || rel % linesPerChunk != 0)
                bad(where + " has invalid scanline " + std::to_string(y));
            const size_t index = size_t(rel / linesPerChunk);
            if (seen[index]) bad(where + " repeats scanline " + std::to_string(y));
            seen[index] = true;
            if (size <= 0 || uint64_t(size) > n_ - off - 8)
                bad(where + " data extends past the end of the file (truncated file?)");
            const uint8_t* src = d_ + off + 8;

            const int64_t lines = std::min<int64_t>(linesPerChunk, ht - rel);
            const size_t expected = size_t(lines) * lineBytes;
            const uint8_t* data = src;
            // Both ZIP variants store a chunk raw when deflate would not shrink it.
            if (size_t(size) != expected) {
                if (h.compression == kNone || size_t(size) > expected)
                    bad(where + " has size " + std::to_string(size) + ", expected " +
                        std::to_string(expected));
                if (!zipDecode(src, size_t(size), raw, expected))
                    bad(where + " has corrupt ZIP data");
                data = raw.data();
            }
            decodeLines(h, img, data, size_t(rel), size_t(lines), size_t(w));
        }
        return img;
    }

    static void decodeLines(const Header& h, ImageRGBA32F& img, const uint8_t* p, size_t y0,
                            size_t lines, size_t w) {
        for (size_t l = 0; l < lines; ++l) {
            float* row = img.at(0, uint32_t(y0 + l));
            for (const Channel& c : h.channels) {
                if (c.target < 0) {
                    p += c.bytes() * w;
                    continue;
                }
                float* dst = row + c.target;
                for (size_t x = 0; x < w; ++x, dst += 4) {
                    if (c.type == kHalf) {
                        *dst = halfToFloat(uint16_t(p[0] | p[1] << 8));
                        p += 2;
                    } else if (c.type == kFloat) {
                        *dst = std::bit_cast<float>(getU32(p));
                        p += 4;
                    } else {
                        *dst = float(getU32(p));
                        p += 4;
                    }
                }
            }
        }
    }

    const std::string& path_;
    const uint8_t* d_;
    size_t n_;
    size_t pos_ = 0;
};

}  // namespace

ImageRGBA32F ImageRGBA32F::blank(uint32_t w, uint32_t h) {
    ImageRGBA32F img;
    img.width = w;
    img.height = h;
    img.rgba.assign(size_t(w) * h * 4, 0.0f);
    for (size_t i = 3; i < img.rgba.size(); i += 4) img.rgba[i] = 1.0f;
    return img;
}

void writeExr(const std::string& path, const ImageRGBA32F& img) {
    if (img.width == 0 || img.height == 0)
        fail(path, "cannot write an empty image (" + std::to_string(img.width) + "x" +
                       std::to_string(img.height) + ")");
    if (img.width > uint32_t(std::numeric_limits<int32_t>::max()) ||
        img.height > uint32_t(std::numeric_limits<int32_t>::max()))
        fail(path, "image too large for OpenEXR");
    if (img.rgba.size() != img.pixelCount() * 4)
        fail(path, "image has " + std::to_string(img.rgba.size()) + " floats, expected " +
                       std::to_string(img.pixelCount() * 4));

    constexpr uint32_t kLinesPerChunk = 16;
    const int32_t xMax = int32_t(img.width - 1), yMax = int32_t(img.height - 1);
    std::vector<uint8_t> out(kMagic, kMagic + 4);
    putU32(out, 2);  // version 2, single-part scanline, short names

    // Channels must be sorted by name, hence B, G, R.
    putStr(out, "channels");
    putStr(out, "chlist");
    putI32(out, 3 * (2 + 16) + 1);
    for (const char* ch : {"B", "G", "R"}) {
        putStr(out, ch);
        putI32(out, kFloat);
        putU32(out, 0);  // pLinear + 3 reserved bytes
        putI32(out, 1);  // xSampling
        putI32(out, 1);  // ySampling
    }
    out.push_back(0);

    putStr(out, "compression");
    putStr(out, "compression");
    putI32(out, 1);
    out.push_back(kZip);

    for (const char* win : {"dataWindow", "displayWindow"}) {
        putStr(out, win);
        putStr(out, "box2i");
        putI32(out, 16);
        for (int32_t v : {0, 0, xMax, yMax}) putI32(out, v);
    }

    putStr(out, "lineOrder");
    putStr(out, "lineOrder");
    putI32(out, 1);
    out.push_back(0);  // INCREASING_Y

    putStr(out, "pixelAspectRatio");
    putStr(out, "float");
    putI32(out, 4);
    putF32(out, 1.0f);

    putStr(out, "screenWindowCenter");
    putStr(out, "v2f");
    putI32(out, 8);
    putF32(out, 0.0f);
    putF32(out, 0.0f);

    putStr(out, "screenWindowWidth");
    putStr(out, "float");
    putI32(out, 4);
    putF32(out, 1.0f);

    out.push_back(0);  // end of header

    const uint32_t chunks = (img.height + kLinesPerChunk - 1) / kLinesPerChunk;
    const size_t tablePos = out.size();
    out.resize(out.size() + size_t(chunks) * 8);

    std::vector<uint8_t> raw;
    for (uint32_t c = 0; c < chunks; ++c) {
        const uint32_t y0 = c * kLinesPerChunk;
        const uint32_t y1 = std::min(img.height, y0 + kLinesPerChunk);
        raw.clear();
        raw.reserve(size_t(y1 - y0) * img.width * 12);
        for (uint32_t y = y0; y < y1; ++y)
            for (int comp : {2, 1, 0})  // B, G, R
                for (uint32_t x = 0; x < img.width; ++x) putF32(raw, img.at(x, y)[comp]);

        std::vector<uint8_t> packed = zipEncode(raw);
        const std::vector<uint8_t>& data = (!packed.empty() && packed.size() < raw.size()) ? packed : raw;
        if (data.size() > size_t(std::numeric_limits<int32_t>::max()))
            fail(path, "chunk too large for OpenEXR");

        putU64At(out, tablePos + size_t(c) * 8, out.size());
        putI32(out, int32_t(y0));
        putI32(out, int32_t(data.size()));
        out.insert(out.end(), data.begin(), data.end());
    }
    detail::writeFileBytes(path, out);
}

ImageRGBA32F readExr(const std::string& path) {
    const std::vector<uint8_t> bytes = detail::readFileBytes(path);
    return Parser(path, bytes).parse();
}

}  // namespace dvsgi::image

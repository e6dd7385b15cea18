// OBJ, MTL and PLY pre-checks: a small reader of each format's structure that
// walks the whole file once (linear in its size) and rejects what assimp
// cannot survive, with a message naming the file and the line or element.
#include "scene/precheck.h"

#include <algorithm>
#include <cctype>
#include <cfloat>
#include <charconv>
#include <cmath>
#include <cstring>
#include <string_view>

#include "scene/import_util.h"
#include "scene/load.h"

namespace dvsgi::scene::detail {

namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what) {
    throw LoadError(printable(path + ": " + what));
}

bool parseDouble(std::string_view t, double& out) {
    if (!t.empty() && t.front() == '+') t.remove_prefix(1);
    auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), out);
    if (ec == std::errc::result_out_of_range) {
        // Beyond double: treat as infinite so the finiteness check names it.
        out = HUGE_VAL;
        return end == t.data() + t.size();
    }
    return ec == std::errc() && end == t.data() + t.size();
}

bool parseInt(std::string_view t, int64_t& out) {
    if (!t.empty() && t.front() == '+') t.remove_prefix(1);
    auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), out);
    return ec == std::errc() && end == t.data() + t.size();
}

// Splits one line into whitespace-separated tokens.
std::vector<std::string_view> tokens(std::string_view line) {
    std::vector<std::string_view> out;
    size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r' || line[i] == '\f' ||
                                   line[i] == '\v'))
            ++i;
        size_t start = i;
        while (i < line.size() && !(line[i] == ' ' || line[i] == '\t' || line[i] == '\r' || line[i] == '\f' ||
                                    line[i] == '\v'))
            ++i;
        if (i > start) out.push_back(line.substr(start, i - start));
    }
    return out;
}

// Calls fn(lineNumber, line) for every line of `data`.
template <typename Fn>
void forEachLine(const uint8_t* data, size_t size, Fn&& fn) {
    std::string_view all(reinterpret_cast<const char*>(data), size);
    size_t pos = 0;
    size_t number = 1;
    while (pos < all.size()) {
        size_t nl = all.find('\n', pos);
        if (nl == std::string_view::npos) nl = all.size();
        fn(number, all.substr(pos, nl - pos));
        pos = nl + 1;
        ++number;
    }
}

// ---- PLY ----

enum class PlyFormat { Ascii, BinaryLE, BinaryBE };

struct PlyProperty {
    std::string name;
    int type = 0;       // byte size of the value (1, 2, 4, 8)
    bool isFloat = false;
    bool isSigned = false;
    bool list = false;
    int countType = 0;  // byte size of a list's count
    bool countSigned = false;
};

struct PlyElement {
    std::string name;
    uint64_t count = 0;
    std::vector<PlyProperty> props;
};

bool plyType(std::string_view t, int& size, bool& isFloat, bool& isSigned) {
    struct T { const char* a; const char* b; int size; bool f; bool s; };
    static const T types[] = {{"char", "int8", 1, false, true},     {"uchar", "uint8", 1, false, false},
                              {"short", "int16", 2, false, true},   {"ushort", "uint16", 2, false, false},
                              {"int", "int32", 4, false, true},     {"uint", "uint32", 4, false, false},
                              {"float", "float32", 4, true, true},  {"double", "float64", 8, true, true}};
    for (const T& x : types) {
        if (t == x.a || t == x.b) {
            size = x.size;
            isFloat = x.f;
            isSigned = x.s;
            return true;
        }
    }
    return false;
}

class PlyWalker {
public:
    PlyWalker(const std::string& path, const uint8_t* data, size_t size) : path_(path), data_(data), size_(size) {}

    void run() {
        parseHeader();
        uint64_t vertexCount = 0;
        bool haveXyz = false;
        for (const PlyElement& e : elements_) {
            if (e.name != "vertex") continue;
            vertexCount = e.count;
            int found = 0;
            for (const PlyProperty& p : e.props)
                if (!p.list && (p.name == "x" || p.name == "y" || p.name == "z")) ++found;
            haveXyz = found == 3;
        }
        if (!haveXyz) fail(path_, "PLY has no 'vertex' element with x, y and z properties");
        vertexCount_ = vertexCount;
        for (const PlyElement& e : elements_) {
            // Every item takes at least one byte (binary) or two (ASCII value
            // and separator); a count beyond that cannot be backed by data.
            if (e.count > size_ - pos_)
                fail(path_, "PLY element '" + e.name + "' declares " + std::to_string(e.count) +
                                " items but the file is truncated");
            for (uint64_t i = 0; i < e.count; ++i) item(e, i);
        }
    }

private:
    void parseHeader() {
        // The header is text; a hostile file without end_header must not make
        // anyone scan gigabytes for it.
        const size_t limit = std::min<size_t>(size_, 1 << 20);
        std::string_view head(reinterpret_cast<const char*>(data_), limit);
        // Checked first: without it every following data line would be
        // reported as an unknown header keyword, hiding the real problem.
        if (head.find("\nend_header") == std::string_view::npos)
            fail(path_, "PLY header has no end_header line");
        size_t pos = 0, lineNo = 0;
        bool haveFormat = false, ended = false;
        while (pos < head.size()) {
            size_t nl = head.find('\n', pos);
            if (nl == std::string_view::npos) break;
            std::string_view line = head.substr(pos, nl - pos);
            pos = nl + 1;
            ++lineNo;
            auto tk = tokens(line);
            std::string where = "PLY header line " + std::to_string(lineNo);
            if (lineNo == 1) {
                if (tk.size() != 1 || tk[0] != "ply") fail(path_, "not a PLY file (first line is not 'ply')");
                continue;
            }
            if (tk.empty() || tk[0] == "comment" || tk[0] == "obj_info") continue;
            if (tk[0] == "end_header") {
                ended = true;
                break;
            }
            if (tk[0] == "format") {
                if (tk.size() != 3 || tk[2] != "1.0") fail(path_, where + ": unsupported format line");
                if (tk[1] == "ascii") format_ = PlyFormat::Ascii;
                else if (tk[1] == "binary_little_endian") format_ = PlyFormat::BinaryLE;
                else if (tk[1] == "binary_big_endian") format_ = PlyFormat::BinaryBE;
                else fail(path_, where + ": unknown format '" + std::string(tk[1]) + "'");
                haveFormat = true;
            } else if (tk[0] == "element") {
                int64_t n = 0;
                if (tk.size() != 3 || !parseInt(tk[2], n) || n < 0)
                    fail(path_, where + ": element needs a name and a non-negative count");
                elements_.push_back(PlyElement{std::string(tk[1]), static_cast<uint64_t>(n), {}});
            } else if (tk[0] == "property") {
                if (elements_.empty()) fail(path_, where + ": property before any element");
                PlyProperty p;
                bool ok;
                if (tk.size() == 5 && tk[1] == "list") {
                    bool f = false;
                    ok = plyType(tk[2], p.countType, f, p.countSigned) && !f &&
                         plyType(tk[3], p.type, p.isFloat, p.isSigned);
                    p.list = true;
                    p.name = std::string(tk[4]);
                } else {
                    ok = tk.size() == 3 && plyType(tk[1], p.type, p.isFloat, p.isSigned);
                    p.name = std::string(tk[tk.size() - 1]);
                }
                if (!ok) fail(path_, where + ": malformed property");
                elements_.back().props.push_back(p);
            } else {
                fail(path_, where + ": unknown keyword '" + std::string(tk[0]) + "'");
            }
        }
        if (!ended) fail(path_, "PLY header has no end_header line");
        if (!haveFormat) fail(path_, "PLY header has no format line");
        for (const PlyElement& e : elements_)
            if (e.count > 0 && e.props.empty()) fail(path_, "PLY element '" + e.name + "' has no properties");
        pos_ = pos;
    }

    [[noreturn]] void truncated(const PlyElement& e, uint64_t i) {
        fail(path_, "PLY data is truncated (" + e.name + " " + std::to_string(i) + " of " +
                        std::to_string(e.count) + ")");
    }

    // Reads one value of `size` bytes as double (binary formats).
    double binaryValue(int size, bool isFloat, bool isSigned, const PlyElement& e, uint64_t i) {
        if (static_cast<size_t>(size) > size_ - pos_) truncated(e, i);
        uint8_t b[8];
        std::memcpy(b, data_ + pos_, static_cast<size_t>(size));
        pos_ += static_cast<size_t>(size);
        if (format_ == PlyFormat::BinaryBE)
            for (int k = 0; k < size / 2; ++k) std::swap(b[k], b[size - 1 - k]);
        if (isFloat) {
            if (size == 4) {
                float f;
                std::memcpy(&f, b, 4);
                return f;
            }
            double d;
            std::memcpy(&d, b, 8);
            return d;
        }
        uint64_t u = 0;
        for (int k = size - 1; k >= 0; --k) u = (u << 8) | b[k];
        if (isSigned && size < 8 && (u >> (size * 8 - 1)) != 0) return static_cast<double>(u) - std::ldexp(1.0, size * 8);
        return static_cast<double>(u);
    }

    // The next ASCII token of the current item's line.
    double asciiValue(const PlyElement& e, uint64_t i) {
        if (next_ >= line_.size()) fail(path_, "PLY " + e.name + " " + std::to_string(i) + " has too few values");
        double d = 0;
        if (!parseDouble(line_[next_], d))
            fail(path_, "PLY " + e.name + " " + std::to_string(i) + ": '" + std::string(line_[next_]) +
                            "' is not a number");
        ++next_;
        return d;
    }

    void nextAsciiLine(const PlyElement& e, uint64_t i) {
        std::string_view rest(reinterpret_cast<const char*>(data_) + pos_, size_ - pos_);
        for (;;) {
            if (rest.empty()) truncated(e, i);
            size_t nl = rest.find('\n');
            std::string_view line = rest.substr(0, nl == std::string_view::npos ? rest.size() : nl);
            size_t used = nl == std::string_view::npos ? rest.size() : nl + 1;
            pos_ += used;
            rest.remove_prefix(used);
            line_ = tokens(line);
            next_ = 0;
            if (!line_.empty()) return;
        }
    }

    double value(int size, bool isFloat, bool isSigned, const PlyElement& e, uint64_t i) {
        return format_ == PlyFormat::Ascii ? asciiValue(e, i) : binaryValue(size, isFloat, isSigned, e, i);
    }

    void item(const PlyElement& e, uint64_t i) {
        if (format_ == PlyFormat::Ascii) nextAsciiLine(e, i);
        const bool vertex = e.name == "vertex";
        const bool face = e.name == "face" || e.name == "tristrips";
        for (const PlyProperty& p : e.props) {
            if (!p.list) {
                double v = value(p.type, p.isFloat, p.isSigned, e, i);
                if (vertex && (p.name == "x" || p.name == "y" || p.name == "z") && !(std::abs(v) <= FLT_MAX))
                    fail(path_, "PLY vertex " + std::to_string(i) + " has a non-finite position");
                continue;
            }
            double n = value(p.countType, false, p.countSigned, e, i);
            const bool indices = face && (p.name == "vertex_indices" || p.name == "vertex_index");
            if (n < 0 || n != std::floor(n) || n > static_cast<double>(size_))
                fail(path_, "PLY " + e.name + " " + std::to_string(i) + " has an invalid list length");
            const uint64_t count = static_cast<uint64_t>(n);
            if (indices && e.name == "face" && (count < 3 || count > kMaxPolygonCorners))
                fail(path_, "PLY face " + std::to_string(i) + " has " + std::to_string(count) +
                                " vertex indices (need 3 to " + std::to_string(kMaxPolygonCorners) + ")");
            if (format_ != PlyFormat::Ascii && !indices) {
                if (count * static_cast<uint64_t>(p.type) > size_ - pos_) truncated(e, i);
                pos_ += static_cast<size_t>(count * static_cast<uint64_t>(p.type));
                continue;
            }
            for (uint64_t k = 0; k < count; ++k) {
                double v = value(p.type, p.isFloat, p.isSigned, e, i);
                // Triangle strips separate their runs with -1.
                if (indices && !(v == -1 && e.name == "tristrips") &&
                    (v < 0 || v >= static_cast<double>(vertexCount_) || v != std::floor(v)))
                    fail(path_, "PLY " + e.name + " " + std::to_string(i) + " refers to vertex " +
                                    std::to_string(static_cast<int64_t>(v)) + " of " +
                                    std::to_string(vertexCount_));
            }
        }
    }

    const std::string& path_;
    const uint8_t* data_;
    size_t size_;
    size_t pos_ = 0;
    PlyFormat format_ = PlyFormat::Ascii;
    std::vector<PlyElement> elements_;
    uint64_t vertexCount_ = 0;
    std::vector<std::string_view> line_;
    size_t next_ = 0;
};

// ---- OBJ ----

struct ObjCounts {
    int64_t v = 0, vt = 0, vn = 0;
};

// One face/line/point corner "v", "v/vt", "v//vn" or "v/vt/vn" against the
// totals of the file (assimp resolves positive indices at the end) and the
// counts so far (negative indices are relative to the current position).
void checkCorner(const std::string& path, size_t lineNo, std::string_view ref, const ObjCounts& total,
                 const ObjCounts& sofar) {
    const std::string where = "line " + std::to_string(lineNo);
    std::string_view parts[3];
    int n = 0;
    size_t start = 0;
    for (size_t k = 0; k <= ref.size(); ++k) {
        if (k == ref.size() || ref[k] == '/') {
            if (n == 3) fail(path, where + ": malformed vertex reference '" + std::string(ref) + "'");
            parts[n++] = ref.substr(start, k - start);
            start = k + 1;
        }
    }
    const int64_t totals[3] = {total.v, total.vt, total.vn};
    const int64_t sofars[3] = {sofar.v, sofar.vt, sofar.vn};
    static const char* names[3] = {"vertex", "texture coordinate", "normal"};
    for (int k = 0; k < n; ++k) {
        if (k > 0 && parts[k].empty()) continue;
        int64_t idx = 0;
        if (!parseInt(parts[k], idx) || idx == 0)
            fail(path, where + ": malformed vertex reference '" + std::string(ref) + "'");
        bool ok = idx > 0 ? idx <= totals[k] : -idx <= sofars[k];
        if (!ok)
            fail(path, where + ": " + names[k] + " index " + std::to_string(idx) + " out of range (" +
                           std::to_string(idx > 0 ? totals[k] : sofars[k]) + " defined)");
    }
}

enum class ObjStatement { Other, V, VT, VN, Face, Unknown };

// Classifies a statement the way assimp's OBJ parser does: by its first one
// or two characters, not the whole keyword ("vtx" is a texture coordinate,
// "f12" a face). Names that assimp would misread as geometry are Unknown.
ObjStatement objStatement(std::string_view kw) {
    if (kw == "v") return ObjStatement::V;
    if (kw == "vt") return ObjStatement::VT;
    if (kw == "vn") return ObjStatement::VN;
    if (kw == "f" || kw == "l" || kw == "p") return ObjStatement::Face;
    if (kw.front() == 'f' || kw.front() == 'l' || kw.front() == 'p') return ObjStatement::Unknown;
    if (kw.size() >= 2 && kw[0] == 'v' && (kw[1] == 't' || kw[1] == 'n')) return ObjStatement::Unknown;
    return ObjStatement::Other;
}

void checkNumbers(const std::string& path, size_t lineNo, const std::vector<std::string_view>& tk, size_t min,
                  size_t max, bool finite) {
    const std::string where = "line " + std::to_string(lineNo) + " ('" + std::string(tk[0]) + "')";
    if (tk.size() - 1 < min) fail(path, where + ": needs " + std::to_string(min) + " numbers");
    for (size_t k = 1; k < tk.size() && k <= max; ++k) {
        double d = 0;
        if (!parseDouble(tk[k], d)) fail(path, where + ": '" + std::string(tk[k]) + "' is not a number");
        // Beyond FLT_MAX the value becomes infinite once stored as float.
        if (finite && !(std::abs(d) <= FLT_MAX))
            fail(path, where + ": value '" + std::string(tk[k]) + "' is not finite (or beyond single precision)");
    }
}

}  // namespace

void precheckPly(const std::string& path, const uint8_t* data, size_t size) {
    PlyWalker(path, data, size).run();
}

std::vector<std::string> precheckObj(const std::string& path, const uint8_t* data, size_t size) {
    ObjCounts total;
    forEachLine(data, size, [&](size_t, std::string_view line) {
        auto tk = tokens(line);
        if (tk.empty()) return;
        switch (objStatement(tk[0])) {
        case ObjStatement::V: ++total.v; break;
        case ObjStatement::VT: ++total.vt; break;
        case ObjStatement::VN: ++total.vn; break;
        default: break;
        }
    });
    ObjCounts sofar;
    std::vector<std::string> mtllibs;
    forEachLine(data, size, [&](size_t lineNo, std::string_view line) {
        auto tk = tokens(line);
        if (tk.empty() || tk[0].front() == '#') return;
        const std::string_view kw = tk[0];
        const ObjStatement kind = objStatement(kw);
        if (kind == ObjStatement::Unknown)
            fail(path, "line " + std::to_string(lineNo) + ": unknown statement '" + std::string(kw) +
                           "' (assimp would read it as '" + kw.front() + "')");
        if (kind == ObjStatement::V) {
            // Positions must be finite: they decide the bounds and the voxel grid.
            checkNumbers(path, lineNo, tk, 3, 3, true);
            ++sofar.v;
        } else if (kind == ObjStatement::VT) {
            checkNumbers(path, lineNo, tk, 1, 3, true);
            ++sofar.vt;
        } else if (kind == ObjStatement::VN) {
            // Non-finite normals are repaired later (replaced by the face normal).
            checkNumbers(path, lineNo, tk, 3, 3, false);
            ++sofar.vn;
        } else if (kind == ObjStatement::Face) {
            const size_t min = kw == "f" ? 3 : kw == "l" ? 2 : 1;
            const size_t corners = tk.size() - 1;
            if (corners < min || corners > kMaxPolygonCorners)
                fail(path, "line " + std::to_string(lineNo) + ": '" + std::string(kw) + "' with " +
                               std::to_string(corners) + " vertices (need " + std::to_string(min) + " to " +
                               std::to_string(kMaxPolygonCorners) + ")");
            for (size_t k = 1; k < tk.size(); ++k) checkCorner(path, lineNo, tk[k], total, sofar);
        } else if (kw == "mtllib") {
            // A file name may contain spaces; assimp takes the rest of the line.
            size_t at = line.find("mtllib") + 6;
            std::string name(line.substr(at));
            while (!name.empty() && std::isspace(static_cast<unsigned char>(name.front()))) name.erase(0, 1);
            while (!name.empty() && std::isspace(static_cast<unsigned char>(name.back()))) name.pop_back();
            for (char& ch : name)
                if (ch == '\\') ch = '/';
            if (!name.empty()) mtllibs.push_back(name);
        }
    });
    return mtllibs;
}

void precheckMtl(const std::string& path, const uint8_t* data, size_t size) {
    forEachLine(data, size, [&](size_t lineNo, std::string_view line) {
        auto tk = tokens(line);
        if (tk.empty()) return;
        const std::string_view kw = tk[0];
        // Values that become material factors: NaN or infinity here would
        // reach the shaders (e.g. "d nan" as opacity).
        if (kw == "Kd" || kw == "Ka" || kw == "Ks" || kw == "Ke" || kw == "Tf") {
            if (tk.size() >= 2 && tk[1] == "spectral") return;  // not read by assimp as a colour
            if (tk.size() >= 2 && tk[1] == "xyz") return;
            checkNumbers(path, lineNo, tk, 1, 3, true);
        } else if (kw == "d" || kw == "Tr" || kw == "Ns" || kw == "Ni") {
            if (kw == "d" && tk.size() >= 2 && tk[1] == "-halo") return;
            checkNumbers(path, lineNo, tk, 1, 1, true);
        }
    });
}

bool precheckImageData(const uint8_t* data, size_t size, uint64_t width, uint64_t height, std::string& error) {
    auto u16 = [&](size_t at) { return uint64_t(data[at]) | uint64_t(data[at + 1]) << 8; };
    auto u32 = [&](size_t at) { return u16(at) | u16(at + 2) << 16; };
    const bool png = size >= 8 && data[0] == 0x89 && data[1] == 'P' && data[2] == 'N' && data[3] == 'G';
    const bool bmp = !png && size >= 2 && data[0] == 'B' && data[1] == 'M';
    const bool tga = !png && !bmp && !isJpeg(data, size);  // the only other format enabled
    // The most texels one byte can describe: deflate of 1-bit rows (PNG)
    // about 8300, a BMP RLE run 255 per 2 bytes, a TGA run packet 128 per 2.
    const uint64_t perByte = tga ? 128 : bmp ? 256 : 16384;
    const uint64_t texels = width * height;
    if (texels > uint64_t(size) * perByte) {
        error = "image header claims " + std::to_string(width) + "x" + std::to_string(height) +
                " texels, more than " + std::to_string(size) + " bytes of data can hold";
        return false;
    }
    uint64_t need = 0;
    if (bmp && size >= 34) {
        const uint64_t offset = u32(10), header = u32(14);
        const uint64_t bpp = header >= 40 ? u16(28) : u16(24);
        const uint64_t compression = header >= 40 ? u32(30) : 0;
        if (compression == 0 || compression == 3)  // BI_RGB, BI_BITFIELDS: every row stored
            need = offset + (bpp * width + 31) / 32 * 4 * height;
    } else if (tga && size >= 18 && (data[2] == 1 || data[2] == 2 || data[2] == 3)) {
        // Uncompressed TGA (types 9-11 are run-length encoded).
        const uint64_t cmap = data[1] ? u16(5) * ((uint64_t(data[7]) + 7) / 8) : 0;
        need = 18 + data[0] + cmap + width * height * ((uint64_t(data[16]) + 7) / 8);
    }
    if (need > size) {
        error = "image data is truncated (" + std::to_string(size) + " of " + std::to_string(need) + " bytes)";
        return false;
    }
    return true;
}

std::vector<uint8_t> withoutEmptyPngIdat(const uint8_t* data, size_t size) {
    static const uint8_t signature[8] = {0x89, 'P', 'N', 'G', 0x0D, 0x0A, 0x1A, 0x0A};
    if (size < 8 || std::memcmp(data, signature, 8) != 0) return {};
    std::vector<size_t> empty;  // offsets of zero-length IDAT chunks (12 bytes each)
    size_t pos = 8;
    while (pos + 12 <= size) {
        const size_t len = (size_t(data[pos]) << 24) | (size_t(data[pos + 1]) << 16) |
                           (size_t(data[pos + 2]) << 8) | data[pos + 3];
        if (len == 0 && std::memcmp(data + pos + 4, "IDAT", 4) == 0) empty.push_back(pos);
        if (len > size - pos - 12) break;  // truncated: the decoder reports it
        pos += 12 + len;
    }
    if (empty.empty()) return {};
    std::vector<uint8_t> out;
    out.reserve(size);
    size_t from = 0;
    for (size_t at : empty) {
        out.insert(out.end(), data + from, data + at);
        from = at + 12;
    }
    out.insert(out.end(), data + from, data + size);
    return out;
}

}  // namespace dvsgi::scene::detail

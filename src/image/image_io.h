// Linear RGBA float images: OpenEXR in/out (through the OpenEXR library), an
// 8-bit sRGB PNG preview, box downsampling and the reference-comparison
// metrics of /work/shared/tools.
#pragma once

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace dvsgi::image {

// Row-major RGBA, row 0 = top of the image. Values are linear radiance
// (W·m⁻²·sr⁻¹) wherever the renderer produces them; nothing here assumes a range.
struct ImageRGBA32F {
    uint32_t width = 0, height = 0;
    std::vector<float> rgba;  // width * height * 4

    // A width x height image, every channel 0 except alpha 1.
    static ImageRGBA32F blank(uint32_t w, uint32_t h);

    float* at(uint32_t x, uint32_t y) { return rgba.data() + (size_t(y) * width + x) * 4; }
    const float* at(uint32_t x, uint32_t y) const {
        return rgba.data() + (size_t(y) * width + x) * 4;
    }
    size_t pixelCount() const { return size_t(width) * height; }
};

// Every I/O failure. what() starts with the file path, then ": ", then the problem.
struct IoError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Sample type of the channels an EXR writer stores. Images are float in
// memory either way; HALF halves the file at 11 significant bits and a range
// of ±65504 (larger values become ±infinity).
enum class PixelType { Float, Half };

struct ExrOptions {
    PixelType type = PixelType::Float;
    bool alpha = false;  // also store A (frames are opaque radiance, so off by default)
};

// Every EXR this module writes is a single-part scanline file with ZIP
// compression, INCREASING_Y, data and display window (0,0)-(w-1,h-1). It is
// written to a temporary file beside `path` and renamed over it only when
// complete, so a failure leaves no partial file (and keeps an older one).
// Missing parent directories are created.

// Channels R, G, B as FLOAT (alpha is dropped).
void writeExr(const std::string& path, const ImageRGBA32F& img);
// Channels R, G, B (and A if options.alpha) as options.type.
void writeExr(const std::string& path, const ImageRGBA32F& img, const ExrOptions& options);

// Reads any OpenEXR file that the OpenEXR library reads (scanline or tiled,
// any compression, HALF, FLOAT or UINT samples; the first part of a multi-part
// file). R, G, B are required; A defaults to 1; other channels are ignored.
// The result covers the data window. Data windows over 2^28 pixels are
// rejected from the header, before anything is allocated for them. Any
// problem (missing, malformed, truncated file) throws IoError.
ImageRGBA32F readExr(const std::string& path);

// One named layer of a multi-layer (AOV) EXR. Channels are stored as
// "<name>.<channel>", the convention OpenImageIO, Nuke and Blender use to
// group channels into layers; an empty name stores the channels unprefixed
// (the default layer viewers show first). Conventional channel names:
//   colour terms   "R","G","B" (direct, indirect, specular, albedo; "A" for a 4th)
//   one scalar     "Y" for a grey value (ao), "Z" for depth
//   a direction    "X","Y","Z" (normal)
struct ExrLayer {
    std::string name;
    std::vector<std::string> channels;  // 1, 3 or 4 names, none empty or containing '.'
    // width * height * channels.size() floats, interleaved per pixel in the
    // order of `channels`, row 0 = top.
    std::vector<float> pixels;
};

// Writes all layers into one EXR (see above for the file layout); every
// channel is stored as `type`. Throws IoError naming the file if the layers
// are inconsistent (sizes, channel counts, names repeated) or writing fails.
void writeExrLayers(const std::string& path, uint32_t width, uint32_t height,
                    const std::vector<ExrLayer>& layers, PixelType type);

// What readExrLayers found: the channels of the file grouped by the text
// before their last '.', layers sorted by name, a layer's channels in the
// order R, G, B, A, X, Y, Z, then the rest alphabetically.
struct ExrLayerFile {
    uint32_t width = 0, height = 0;  // of the data window
    std::vector<ExrLayer> layers;
    std::vector<PixelType> types;  // stored sample type of each layer
};

// Reads every layer of an EXR written by writeExrLayers (or any file with
// HALF/FLOAT channels that are not subsampled). Throws IoError as readExr does,
// and for UINT channels or a layer that mixes HALF and FLOAT.
ExrLayerFile readExrLayers(const std::string& path);

// Writes an 8-bit RGB sRGB preview (alpha dropped). Per channel:
//   v = linear * 2^exposureEV, clamped to [0, 1] (NaN -> 0, +Inf -> 1)
//   s = 12.92 v                      if v <= 0.0031308
//       1.055 v^(1/2.4) - 0.055      otherwise          (sRGB OETF)
//   byte = round(255 s)
// No other tone mapping: this is the same encoding as the reference PNGs
// (e.g. linear 0.3183107 at 0 EV -> 153). Creates missing parent directories.
void writePng(const std::string& path, const ImageRGBA32F& img, float exposureEV);

// The sRGB byte writePng stores for one linear channel value (already scaled
// by the exposure).
uint8_t encodeSrgb8(float linear);

// Averages factor x factor blocks of all four channels, i.e. turns point
// samples of a k-times supersampled frame into pixel-area averages. Throws
// std::invalid_argument if factor is 0 or does not divide width and height.
ImageRGBA32F downsampleBox(const ImageRGBA32F& img, uint32_t factor);

// The metrics of /work/shared/tools/compare.py (which stays the definition),
// computed on R, G, B only, over pixels whose RGB is finite in both images:
//   relRmse       sqrt(mean (c - r)^2) / sqrt(mean r^2)        (inf if r == 0)
//   meanLumRatio  mean Y(c) / mean Y(r), Y = 0.2126 R + 0.7152 G + 0.0722 B
//   relRmsePixel  sqrt(mean (c - r)^2 / (r^2 + 0.01))
//   fracWithinTol fraction of all pixels with |Y(c) - Y(r)| <= 0.10 max(Y(r), floor),
//                 floor = max(0.01 mean Y(r), 1e-12); non-finite pixels fail
struct ImageStats {
    double relRmse = 0.0;
    double meanLumRatio = 0.0;
    double relRmsePixel = 0.0;
    double fracWithinTol = 0.0;
};

// Throws std::invalid_argument if the sizes differ.
ImageStats compareImages(const ImageRGBA32F& candidate, const ImageRGBA32F& reference);

// /work/shared/tools/masked_rmse.py: relative RMSE over the pixels whose 5x5
// neighbourhood (edge-padded) of reference luminance varies by at most 20 % of
// its maximum, i.e. away from edges where a pixel offset dominates the error.
// fractionKept (optional) receives the fraction of pixels used. NaN if none is
// kept. Throws std::invalid_argument if the sizes differ.
double maskedRelRmse(const ImageRGBA32F& candidate, const ImageRGBA32F& reference,
                     double* fractionKept = nullptr);

}  // namespace dvsgi::image

// Linear RGBA float images: OpenEXR in/out, an 8-bit sRGB PNG preview, box
// downsampling and the reference-comparison metrics of /work/shared/tools.
//
// The EXR code is a deliberately small, self-contained subset of OpenEXR 2.0
// (single-part scanline files only) so the renderer does not depend on the
// OpenEXR library; OpenImageIO is used by the tests to check compatibility.
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

// Writes a single-part scanline OpenEXR file with FLOAT channels B, G, R (alpha
// is dropped: frames are opaque radiance), ZIP compression (16 lines per
// chunk; a chunk that would not shrink is stored raw, as the format allows),
// INCREASING_Y. Creates missing parent directories.
void writeExr(const std::string& path, const ImageRGBA32F& img);

// Reads a single-part scanline OpenEXR file with NO_COMPRESSION, ZIPS or ZIP
// compression and HALF, FLOAT or UINT channels. R, G, B are required; A
// defaults to 1; other channels are ignored. The result covers the data
// window. Anything else, or any inconsistency in the file, throws IoError.
ImageRGBA32F readExr(const std::string& path);

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

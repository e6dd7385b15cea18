// Downsampling and the reference metrics. The metrics mirror the numpy code of
// /work/shared/tools/compare.py and masked_rmse.py step by step (float64,
// same masks, same NaN behaviour) so C++ tests and the Python tools agree.
#include "image/image_io.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace dvsgi::image {

ImageRGBA32F ImageRGBA32F::blank(uint32_t w, uint32_t h) {
    ImageRGBA32F img;
    img.width = w;
    img.height = h;
    img.rgba.assign(size_t(w) * h * 4, 0.0f);
    for (size_t i = 3; i < img.rgba.size(); i += 4) img.rgba[i] = 1.0f;
    return img;
}

namespace {

constexpr double kLum[3] = {0.2126, 0.7152, 0.0722};

double lum(const float* p) { return kLum[0] * p[0] + kLum[1] * p[1] + kLum[2] * p[2]; }

bool finiteRgb(const float* p) {
    return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
}

void requireSameSize(const ImageRGBA32F& a, const ImageRGBA32F& b, const char* fn) {
    if (a.width != b.width || a.height != b.height)
        throw std::invalid_argument(std::string(fn) + ": size mismatch, candidate " +
                                    std::to_string(a.width) + "x" + std::to_string(a.height) +
                                    ", reference " + std::to_string(b.width) + "x" +
                                    std::to_string(b.height));
}

}  // namespace

ImageRGBA32F downsampleBox(const ImageRGBA32F& img, uint32_t factor) {
    if (factor == 0 || img.width % factor != 0 || img.height % factor != 0)
        throw std::invalid_argument("downsampleBox: factor " + std::to_string(factor) +
                                    " does not divide " + std::to_string(img.width) + "x" +
                                    std::to_string(img.height));
    ImageRGBA32F out = ImageRGBA32F::blank(img.width / factor, img.height / factor);
    const double norm = 1.0 / (double(factor) * factor);
    for (uint32_t y = 0; y < out.height; ++y)
        for (uint32_t x = 0; x < out.width; ++x) {
            double sum[4] = {0, 0, 0, 0};
            for (uint32_t dy = 0; dy < factor; ++dy)
                for (uint32_t dx = 0; dx < factor; ++dx) {
                    const float* p = img.at(x * factor + dx, y * factor + dy);
                    for (int c = 0; c < 4; ++c) sum[c] += p[c];
                }
            float* o = out.at(x, y);
            for (int c = 0; c < 4; ++c) o[c] = float(sum[c] * norm);
        }
    return out;
}

ImageStats compareImages(const ImageRGBA32F& candidate, const ImageRGBA32F& reference) {
    requireSameSize(candidate, reference, "compareImages");
    const size_t n = candidate.pixelCount();
    const double inf = std::numeric_limits<double>::infinity();
    const double nan = std::numeric_limits<double>::quiet_NaN();

    size_t ok = 0;
    double sumD2 = 0, sumR2 = 0, sumYc = 0, sumYr = 0, sumRelPix = 0;
    for (size_t i = 0; i < n; ++i) {
        const float* c = &candidate.rgba[i * 4];
        const float* r = &reference.rgba[i * 4];
        if (!finiteRgb(c) || !finiteRgb(r)) continue;
        ++ok;
        for (int k = 0; k < 3; ++k) {
            const double d = double(c[k]) - double(r[k]);
            sumD2 += d * d;
            sumR2 += double(r[k]) * r[k];
            sumRelPix += d * d / (double(r[k]) * r[k] + 0.01);
        }
        sumYc += lum(c);
        sumYr += lum(r);
    }

    ImageStats s;
    const double meanYr = ok ? sumYr / ok : 0.0;
    if (ok) {
        const double rmse = std::sqrt(sumD2 / (3.0 * ok));
        const double rmsRef = std::sqrt(sumR2 / (3.0 * ok));
        s.relRmse = rmsRef > 0 ? rmse / rmsRef : inf;
        s.relRmsePixel = std::sqrt(sumRelPix / (3.0 * ok));
    } else {
        s.relRmse = inf;
        s.relRmsePixel = nan;
    }
    s.meanLumRatio = meanYr > 0 ? (sumYc / ok) / meanYr : inf;

    // Pixels that failed the finiteness test count as outside the tolerance.
    const double floor = std::max(0.01 * meanYr, 1e-12);
    size_t within = 0;
    for (size_t i = 0; i < n; ++i) {
        const float* c = &candidate.rgba[i * 4];
        const float* r = &reference.rgba[i * 4];
        if (!finiteRgb(c) || !finiteRgb(r)) continue;
        const double yr = lum(r);
        if (std::abs((lum(c) - yr) / std::max(yr, floor)) <= 0.10) ++within;
    }
    s.fracWithinTol = n ? double(within) / double(n) : nan;
    return s;
}

double maskedRelRmse(const ImageRGBA32F& candidate, const ImageRGBA32F& reference,
                     double* fractionKept) {
    requireSameSize(candidate, reference, "maskedRelRmse");
    const int w = int(reference.width), h = int(reference.height);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    std::vector<double> y(size_t(w) * h);
    for (size_t i = 0; i < y.size(); ++i) y[i] = lum(&reference.rgba[i * 4]);

    constexpr int k = 2;  // 5x5 window
    size_t kept = 0;
    double sumD2 = 0, sumR2 = 0;
    for (int py = 0; py < h; ++py)
        for (int px = 0; px < w; ++px) {
            // numpy's max/min propagate NaN, which then fails the comparison.
            double mx = -std::numeric_limits<double>::infinity();
            double mn = std::numeric_limits<double>::infinity();
            bool hasNan = false;
            for (int dy = -k; dy <= k; ++dy)
                for (int dx = -k; dx <= k; ++dx) {
                    const int sx = std::clamp(px + dx, 0, w - 1);  // edge padding
                    const int sy = std::clamp(py + dy, 0, h - 1);
                    const double v = y[size_t(sy) * w + sx];
                    if (std::isnan(v)) hasNan = true;
                    mx = std::max(mx, v);
                    mn = std::min(mn, v);
                }
            if (hasNan || !((mx - mn) <= 0.2 * std::max(mx, 1e-6))) continue;
            ++kept;
            const float* c = candidate.at(uint32_t(px), uint32_t(py));
            const float* r = reference.at(uint32_t(px), uint32_t(py));
            for (int ch = 0; ch < 3; ++ch) {
                const double d = double(c[ch]) - double(r[ch]);
                sumD2 += d * d;
                sumR2 += double(r[ch]) * r[ch];
            }
        }
    if (fractionKept) *fractionKept = y.empty() ? nan : double(kept) / double(y.size());
    if (kept == 0) return nan;
    return std::sqrt(sumD2 / (3.0 * kept)) / std::sqrt(sumR2 / (3.0 * kept));
}

}  // namespace dvsgi::image

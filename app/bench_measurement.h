// One (scene, N) measurement of `dvsgi bench` and the statistics of its
// samples, shared by the command (bench_command.cpp) and its reports.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bench/bytes_model.h"

namespace dvsgi::app {

// Median, minimum, maximum and mean of a list of samples.
struct Summary {
    double median = 0.0, min = 0.0, max = 0.0, mean = 0.0;
};

inline Summary summarize(std::vector<double> v) {
    Summary s;
    if (v.empty()) return s;
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    s.median = n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
    s.min = v.front();
    s.max = v.back();
    double sum = 0.0;
    for (double x : v) sum += x;
    s.mean = sum / double(n);
    return s;
}

// Per-pass samples in the order the passes first appeared, so passes added to
// the renderer later show up without changes here.
struct PassSamples {
    std::vector<std::string> order;
    std::map<std::string, std::vector<double>> samples;
    void add(const std::string& name, double ms) {
        auto [it, inserted] = samples.try_emplace(name);
        if (inserted) order.push_back(name);
        it->second.push_back(ms);
    }
};

struct Measurement {
    std::string scene;
    std::string file;
    uint32_t voxels = 0;
    std::string variant;  // "" = defaults; else what differs (Tables III and V)
    std::string status;  // "ok", "failed", "skipped"
    std::string error;
    uint32_t frames = 0;
    PassSamples passes;
    std::vector<double> frameMs;  // the whole frame ("frame" timer)
    std::vector<double> wallMs;   // host time of renderFrame (record, submit, wait)
    uint64_t staticTriangles = 0, dynamicTriangles = 0;
    uint64_t memoryBytes = 0;
    nlohmann::json detail;  // grid, memory items, setup times
    // The bytes model (bench_efficiency.h), filled after the measured frames.
    bool counted = false;  // voxels counted (a measurement with voxels)
    uint64_t occupiedVoxels = 0, dynamicVoxels = 0;
    bench::ModelInputs modelInputs;
    std::vector<bench::PassTraffic> traffic;
    // --camera-path: the indirect term's change from each measured frame to
    // the next (mean and 99th percentile of the relative change, per frame).
    std::vector<double> flickerMean, flickerP99;
    std::vector<double> flickerIrradianceMean, flickerIrradianceP99;  // the same before the albedo
    std::vector<double> scrollJumps;  // mean indirect luminance after / before - 1 at frames where a clipmap scrolled
};

// A markdown table's header: the corner cell, then one column per measurement
// ("scene N^3 variant"), and the separator line.
inline void printColumnsHeader(const std::string& corner, const std::vector<const Measurement*>& cols) {
    std::printf("| %s |", corner.c_str());
    for (const Measurement* m : cols)
        std::printf(" %s %u^3%s%s |", m->scene.c_str(), m->voxels, m->variant.empty() ? "" : " ", m->variant.c_str());
    std::printf("\n|---|");
    for (size_t i = 0; i < cols.size(); ++i) std::printf("---|");
    std::printf("\n");
}

}  // namespace dvsgi::app

#include "gpu/fault.h"

#include <atomic>
#include <cstdlib>
#include <string>
#include <string_view>

#include "gpu/check.h"

namespace dvsgi::gpu::fault {

namespace {

enum class Kind { None, Oom, DeviceLost, Swapchain };

struct Spec {
    Kind kind = Kind::None;
    std::string name;       // oom: substring of the resource name
    uint64_t submit = 0;    // device-lost: which submission
    std::string error;      // non-empty: DVSGI_FAULT could not be read
};

Spec parse(const char* env) {
    Spec s;
    if (!env || !*env) return s;
    const std::string_view v(env);
    if (v.starts_with("oom:") && v.size() > 4) {
        s.kind = Kind::Oom;
        s.name = v.substr(4);
    } else if (v.starts_with("device-lost@")) {
        const std::string digits(v.substr(12));
        char* end = nullptr;
        const unsigned long long n = std::strtoull(digits.c_str(), &end, 10);
        if (digits.empty() || *end != '\0' || n == 0) s.error = std::string(v);
        s.kind = Kind::DeviceLost;
        s.submit = n;
    } else if (v == "swapchain") {
        s.kind = Kind::Swapchain;
    } else {
        s.error = std::string(v);
    }
    return s;
}

const Spec& spec() {
    static const Spec s = parse(std::getenv("DVSGI_FAULT"));
    if (!s.error.empty())
        throw GpuError("DVSGI_FAULT: '" + s.error +
                           "' is not oom:NAME, device-lost@N (N >= 1) or swapchain (a test-only setting)",
                       VK_ERROR_INITIALIZATION_FAILED);
    return s;
}

std::atomic<uint64_t> g_submissions{0};

}  // namespace

VkResult allocation(const char* name) {
    const Spec& s = spec();
    if (s.kind == Kind::Oom && name && std::string_view(name).find(s.name) != std::string_view::npos)
        return VK_ERROR_OUT_OF_DEVICE_MEMORY;
    return VK_SUCCESS;
}

VkResult submission() {
    const Spec& s = spec();
    const uint64_t n = ++g_submissions;
    return s.kind == Kind::DeviceLost && n == s.submit ? VK_ERROR_DEVICE_LOST : VK_SUCCESS;
}

VkResult swapchain() { return spec().kind == Kind::Swapchain ? VK_ERROR_INITIALIZATION_FAILED : VK_SUCCESS; }

}  // namespace dvsgi::gpu::fault

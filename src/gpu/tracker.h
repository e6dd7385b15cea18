// Remembers how each image and buffer of a frame was last used and emits the
// synchronization2 barriers a pass needs before it runs. A pass declares what
// it is about to do with each resource (an ImageUse, or stages + access for a
// buffer); the tracker compares that with the resource's history:
//   - a different layout, or contents that may be discarded: a layout transition;
//   - a write after earlier writes or reads (WAW, WAR): an execution + memory
//     dependency from all of them;
//   - a read of data written earlier and not yet made visible to that read's
//     stages and accesses (RAW): a memory dependency from the write;
//   - a read after reads, or after a write already visible to it: nothing.
// All barriers declared before flush() go out as one vkCmdPipelineBarrier2.
// The state outlives command buffers: a later submission's barriers order it
// after the earlier submissions on the same queue, so one tracker per Renderer
// covers every frame.
#pragma once

#include <cstdint>
#include <unordered_map>
#include <vector>

#include <vulkan/vulkan.h>

#include "gpu/barriers.h"

namespace dvsgi::gpu {

class Image;
class Buffer;

class Tracker {
public:
    // The next commands use `image` (every mip, or one mip) as `use`.
    // discard: the old contents are not needed (the pass overwrites them all).
    Tracker& image(const Image& image, ImageUse use, bool discard = false);
    Tracker& imageMip(const Image& image, uint32_t mip, ImageUse use, bool discard = false);
    Tracker& buffer(const Buffer& buffer, VkPipelineStageFlags2 stages, VkAccessFlags2 access);
    Tracker& buffer(const Buffer& b, BufferUse use) { return buffer(b, use.stages, use.access); }
    // Records the barriers declared since the last flush (nothing when none is needed).
    void flush(VkCommandBuffer cmd);

    // For code that changed a resource outside the tracker (an upload in its
    // own submission): from now on its history is `use`, with nothing pending.
    void assume(const Image& image, ImageUse use);
    // What flush() would record, for tests.
    const std::vector<VkImageMemoryBarrier2>& pendingImageBarriers() const { return images_; }
    const std::vector<VkBufferMemoryBarrier2>& pendingBufferBarriers() const { return buffers_; }
    // The layout the tracker believes `mip` of `image` is in.
    VkImageLayout layout(const Image& image, uint32_t mip = 0) const;

private:
    struct History {
        VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
        VkPipelineStageFlags2 writeStages = 0;  // the last write (or layout transition)
        VkAccessFlags2 writeAccess = 0;
        VkPipelineStageFlags2 readStages = 0;   // reads since that write
        VkPipelineStageFlags2 visibleStages = 0;  // where the write has been made visible
        VkAccessFlags2 visibleAccess = 0;
    };
    struct Barrier {
        bool needed = false;
        ImageUse from{}, to{};  // from.layout is the old layout (UNDEFINED when discarded)
    };
    static Barrier advance(History& h, ImageUse use, bool discard);
    std::vector<History>& mips(const Image& image);
    void addImageBarrier(const Image& image, uint32_t mip, uint32_t count, const Barrier& b);

    std::unordered_map<uint64_t, std::vector<History>> imageHistory_;  // by Image::serial(), one entry per mip
    std::unordered_map<uint64_t, History> bufferHistory_;  // by Buffer::serial()
    std::vector<VkImageMemoryBarrier2> images_;
    std::vector<VkBufferMemoryBarrier2> buffers_;
};

// Records a small (<= 64 KiB) update of a uniform buffer inside a command
// buffer, ordered after its earlier uses and before any later uniform read.
void recordUniformUpdate(VkCommandBuffer cmd, Tracker& tracker, const Buffer& buffer, const void* data,
                         VkDeviceSize bytes);

}  // namespace dvsgi::gpu

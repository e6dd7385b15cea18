#include "gpu/tracker.h"

#include "gpu/resources.h"

namespace dvsgi::gpu {

namespace {

constexpr VkAccessFlags2 kWriteAccess =
    VK_ACCESS_2_SHADER_WRITE_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT |
    VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT | VK_ACCESS_2_TRANSFER_WRITE_BIT | VK_ACCESS_2_HOST_WRITE_BIT |
    VK_ACCESS_2_MEMORY_WRITE_BIT;

bool sameBarrier(const VkImageMemoryBarrier2& a, const VkImageMemoryBarrier2& b) {
    return a.image == b.image && a.srcStageMask == b.srcStageMask && a.srcAccessMask == b.srcAccessMask &&
           a.dstStageMask == b.dstStageMask && a.dstAccessMask == b.dstAccessMask && a.oldLayout == b.oldLayout &&
           a.newLayout == b.newLayout;
}

}  // namespace

Tracker::Barrier Tracker::advance(History& h, ImageUse use, bool discard) {
    const auto [layout, stages, access] = use;
    Barrier b;
    b.to = use;
    b.from.layout = discard ? VK_IMAGE_LAYOUT_UNDEFINED : h.layout;
    const bool writes = (access & kWriteAccess) != 0;
    if (discard || layout != h.layout) {
        // A layout transition is itself a write: it waits for every earlier
        // use, and later uses in other stages must wait for it.
        b.needed = true;
        b.from.stages = h.writeStages | h.readStages;
        b.from.access = h.writeAccess;
        h = History{layout, stages, writes ? (access & kWriteAccess) : 0, 0, writes ? 0 : stages,
                    writes ? 0 : access};
        return b;
    }
    if (writes) {
        b.needed = (h.writeStages | h.readStages) != 0;
        b.from.stages = h.writeStages | h.readStages;
        b.from.access = h.writeAccess;
        h = History{layout, stages, access & kWriteAccess, 0, 0, 0};
        return b;
    }
    if (h.writeStages != 0 && ((stages & ~h.visibleStages) != 0 || (access & ~h.visibleAccess) != 0)) {
        b.needed = true;
        b.from.stages = h.writeStages;
        b.from.access = h.writeAccess;
        h.visibleStages |= stages;
        h.visibleAccess |= access;
    }
    h.readStages |= stages;
    return b;
}

std::vector<Tracker::History>& Tracker::mips(const Image& image) {
    std::vector<History>& m = imageHistory_[image.serial()];
    if (m.empty()) m.resize(image.desc().mipLevels);
    return m;
}

void Tracker::addImageBarrier(const Image& image, uint32_t mip, uint32_t count, const Barrier& b) {
    const VkImageMemoryBarrier2 ib =
        imageBarrier(image, {image.aspect(), mip, count, 0, VK_REMAINING_ARRAY_LAYERS}, b.from, b.to);
    // Neighbouring mips with the same history share one barrier.
    if (!images_.empty()) {
        VkImageMemoryBarrier2& last = images_.back();
        if (sameBarrier(last, ib) && last.subresourceRange.baseMipLevel + last.subresourceRange.levelCount == mip) {
            last.subresourceRange.levelCount += count;
            return;
        }
    }
    images_.push_back(ib);
}

Tracker& Tracker::image(const Image& image, ImageUse use, bool discard) {
    std::vector<History>& m = mips(image);
    for (uint32_t i = 0; i < uint32_t(m.size()); ++i) {
        const Barrier b = advance(m[i], use, discard);
        if (b.needed) addImageBarrier(image, i, 1, b);
    }
    return *this;
}

Tracker& Tracker::imageMip(const Image& image, uint32_t mip, ImageUse use, bool discard) {
    std::vector<History>& m = mips(image);
    const Barrier b = advance(m.at(mip), use, discard);
    if (b.needed) addImageBarrier(image, mip, 1, b);
    return *this;
}

Tracker& Tracker::buffer(const Buffer& buffer, VkPipelineStageFlags2 stages, VkAccessFlags2 access) {
    const Barrier b = advance(bufferHistory_[buffer.serial()], {VK_IMAGE_LAYOUT_UNDEFINED, stages, access}, false);
    if (!b.needed) return *this;
    VkBufferMemoryBarrier2 bb{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER_2};
    bb.srcStageMask = b.from.stages;
    bb.srcAccessMask = b.from.access;
    bb.dstStageMask = b.to.stages;
    bb.dstAccessMask = b.to.access;
    bb.srcQueueFamilyIndex = bb.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    bb.buffer = buffer.handle();
    bb.size = VK_WHOLE_SIZE;
    buffers_.push_back(bb);
    return *this;
}

void Tracker::flush(VkCommandBuffer cmd) {
    if (images_.empty() && buffers_.empty()) return;
    VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dep.imageMemoryBarrierCount = uint32_t(images_.size());
    dep.pImageMemoryBarriers = images_.data();
    dep.bufferMemoryBarrierCount = uint32_t(buffers_.size());
    dep.pBufferMemoryBarriers = buffers_.data();
    vkCmdPipelineBarrier2(cmd, &dep);
    images_.clear();
    buffers_.clear();
}

void Tracker::assume(const Image& image, ImageUse use) {
    const bool writes = (use.access & kWriteAccess) != 0;
    for (History& h : mips(image))
        h = History{use.layout, use.stages, writes ? (use.access & kWriteAccess) : 0, 0, use.stages, use.access};
}

VkImageLayout Tracker::layout(const Image& image, uint32_t mip) const {
    const auto it = imageHistory_.find(image.serial());
    return it == imageHistory_.end() ? VK_IMAGE_LAYOUT_UNDEFINED : it->second.at(mip).layout;
}

void recordUniformUpdate(VkCommandBuffer cmd, Tracker& tracker, const Buffer& buffer, const void* data,
                         VkDeviceSize bytes) {
    // Passes do not declare their uniform reads: assume one before the write.
    tracker.buffer(buffer, use::BufferUniformRead).buffer(buffer, use::BufferTransferWrite).flush(cmd);
    vkCmdUpdateBuffer(cmd, buffer.handle(), 0, bytes, data);
    tracker.buffer(buffer, use::BufferUniformRead).flush(cmd);
}

}  // namespace dvsgi::gpu

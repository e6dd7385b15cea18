// JPEG textures through libjpeg-turbo. stb_image 2.27's JPEG decoder, the
// system copy, wrote past its Huffman tables and shifted by negative amounts
// on corrupt files (found by fuzz_image); libjpeg-turbo is the decoder the
// distributions fuzz continuously.
#include <csetjmp>
#include <cstdio>

#include <jpeglib.h>

#include "scene/import_util.h"
#include "scene/precheck.h"

namespace dvsgi::scene::detail {

namespace {

struct ErrorManager {
    jpeg_error_mgr pub;
    std::jmp_buf jump;
    char message[JMSG_LENGTH_MAX];
};

[[noreturn]] void onError(j_common_ptr cinfo) {
    auto* e = reinterpret_cast<ErrorManager*>(cinfo->err);
    (*cinfo->err->format_message)(cinfo, e->message);
    std::longjmp(e->jump, 1);
}

// libjpeg prints warnings (corrupt data, premature end of file) to stderr
// and carries on with grey texels; either would break the one-line rule or
// hide damage, so a warning ends the decode like an error.
void onMessage(j_common_ptr cinfo, int level) {
    if (level < 0) onError(cinfo);
}

}  // namespace

bool isJpeg(const uint8_t* data, size_t size) {
    size_t pos = 0;
    while (pos < size && data[pos] == 0xFF) ++pos;
    return pos > 0 && pos < size && data[pos] == 0xD8;
}

bool decodeJpeg(const uint8_t* data, size_t size, Texture& out, std::string& error) {
    jpeg_decompress_struct cinfo;
    ErrorManager err;
    cinfo.err = jpeg_std_error(&err.pub);
    err.pub.error_exit = onError;
    err.pub.emit_message = onMessage;
    // Nothing with a destructor lives in this frame between setjmp and a
    // possible longjmp from inside libjpeg.
    if (setjmp(err.jump)) {
        jpeg_destroy_decompress(&cinfo);
        error = std::string("corrupt JPEG (") + err.message + ")";
        return false;
    }
    jpeg_create_decompress(&cinfo);
    jpeg_mem_src(&cinfo, data, static_cast<unsigned long>(size));
    jpeg_read_header(&cinfo, TRUE);
    const uint64_t w = cinfo.image_width, h = cinfo.image_height;
    if (w * h > kMaxImageTexels) {
        error = "image size " + std::to_string(w) + "x" + std::to_string(h) + " exceeds the limit of " +
                std::to_string(kMaxImageTexels) + " texels";
        jpeg_destroy_decompress(&cinfo);
        return false;
    }
    if (!precheckImageData(data, size, w, h, error)) {
        jpeg_destroy_decompress(&cinfo);
        return false;
    }
    cinfo.out_color_space = JCS_EXT_RGBA;
    jpeg_start_decompress(&cinfo);
    out.width = cinfo.output_width;
    out.height = cinfo.output_height;
    out.rgba8.resize(size_t(out.width) * out.height * 4);
    while (cinfo.output_scanline < cinfo.output_height) {
        JSAMPROW row = &out.rgba8[size_t(cinfo.output_scanline) * out.width * 4];
        jpeg_read_scanlines(&cinfo, &row, 1);
    }
    jpeg_finish_decompress(&cinfo);
    jpeg_destroy_decompress(&cinfo);
    return true;
}

}  // namespace dvsgi::scene::detail

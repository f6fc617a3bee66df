// PNG encoding and decoding through stb (public domain, from libstb-dev), with stb's deflate
// replaced by zlib's: this is the one file that compiles the stb_image(_write) implementations.
#include "rube/render/image.hpp"

#include <zlib.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>
#include <system_error>

#include <unistd.h>

namespace {

// stb allocates a filtered copy of the whole frame (2.8 MB at 1280x720) for every PNG, and
// fresh pages from the system cost ~750 page faults, over 2 ms, per frame. Each thread keeps
// a few freed blocks for its next frame instead. A header before each block records its size.
struct BlockHeader {
    std::size_t capacity;
    std::size_t padding; // keeps the block after the header aligned as malloc's are
};

struct BlockCache {
    static constexpr std::size_t smallest = 64 * 1024; // smaller blocks are cheap: no caching
    BlockHeader* blocks[4] = {nullptr, nullptr, nullptr, nullptr};
    ~BlockCache() {
        for (BlockHeader* block : blocks) std::free(block);
    }
};
thread_local BlockCache blockCache;

void* allocateBlock(std::size_t size) {
    BlockHeader** best = nullptr;
    if (size >= BlockCache::smallest) {
        for (BlockHeader*& block : blockCache.blocks) {
            if (block != nullptr && block->capacity >= size && (best == nullptr || block->capacity < (*best)->capacity))
                best = &block;
        }
    }
    if (best != nullptr) {
        BlockHeader* block = *best;
        *best = nullptr;
        return block + 1;
    }
    auto* block = static_cast<BlockHeader*>(std::malloc(sizeof(BlockHeader) + size));
    if (block == nullptr) return nullptr;
    block->capacity = size;
    return block + 1;
}

void releaseBlock(void* memory) {
    if (memory == nullptr) return;
    BlockHeader* block = static_cast<BlockHeader*>(memory) - 1;
    if (block->capacity >= BlockCache::smallest) {
        for (BlockHeader*& slot : blockCache.blocks) {
            if (slot == nullptr) {
                slot = block;
                return;
            }
        }
    }
    std::free(block);
}

// stb requires it alongside STBIW_MALLOC, though with our deflate it never calls it.
[[maybe_unused]] void* reallocateBlock(void* memory, std::size_t size) {
    if (memory == nullptr) return allocateBlock(size);
    BlockHeader* block = static_cast<BlockHeader*>(memory) - 1;
    if (block->capacity >= size) return memory;
    void* grown = allocateBlock(size);
    if (grown == nullptr) return nullptr;
    std::memcpy(grown, memory, block->capacity);
    releaseBlock(memory);
    return grown;
}

// One deflate stream per thread, reset rather than rebuilt: its ~400 KB of tables would
// otherwise be allocated and faulted in again for every frame.
struct Deflater {
    z_stream stream{};
    bool ready = false;
    ~Deflater() {
        if (ready) deflateEnd(&stream);
    }
};
thread_local Deflater deflater;

// stb's own deflate is simple and slow (~100 ms for a 1280x720 frame). Level 1 with Z_RLE
// matches only runs of repeated bytes, which is what "up"-filtered flat colour is made of:
// ~10 ms and smaller files than stb's level 8. stb frees the result with STBIW_FREE.
unsigned char* deflateWithZlib(unsigned char* data, int length, int* outLength, int /*stbQuality*/) {
    z_stream& stream = deflater.stream;
    if (!deflater.ready) {
        if (deflateInit2(&stream, 1, Z_DEFLATED, 15, 8, Z_RLE) != Z_OK) return nullptr;
        deflater.ready = true;
    } else if (deflateReset(&stream) != Z_OK) {
        return nullptr;
    }
    uLong bound = deflateBound(&stream, static_cast<uLong>(length));
    auto* out = static_cast<unsigned char*>(allocateBlock(bound));
    if (out == nullptr) return nullptr;
    stream.next_in = data;
    stream.avail_in = static_cast<uInt>(length);
    stream.next_out = out;
    stream.avail_out = static_cast<uInt>(bound);
    if (deflate(&stream, Z_FINISH) != Z_STREAM_END) {
        releaseBlock(out);
        return nullptr;
    }
    *outLength = static_cast<int>(stream.total_out);
    return out;
}

} // namespace

// Static: these copies of stb stay private to this file, whatever else links stb.
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STBIW_ZLIB_COMPRESS deflateWithZlib
#define STBIW_MALLOC(size) allocateBlock(size)
#define STBIW_REALLOC(memory, size) reallocateBlock(memory, size)
#define STBIW_FREE(memory) releaseBlock(memory)
#include <stb_image_write.h>

#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#define STBI_NO_LINEAR
#define STBI_NO_HDR
#include <stb_image.h>

namespace rube::render {
namespace {

// Filter 2 ("up") on every row: flat greybox areas become zero bytes, and stb skips trying all
// five filters per row (the default), which costs more than the compression itself.
[[maybe_unused]] const bool upFilterForced = (stbi_write_force_png_filter = 2, true);

std::string reason(int error) { return std::generic_category().message(error); }

} // namespace

Image Image::filled(int width, int height, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    Image image;
    image.resize(width, height);
    for (std::size_t i = 0; i < image.rgb.size(); i += 3) {
        image.rgb[i] = r;
        image.rgb[i + 1] = g;
        image.rgb[i + 2] = b;
    }
    return image;
}

void Image::resize(int newWidth, int newHeight) {
    width = newWidth < 0 ? 0 : newWidth;
    height = newHeight < 0 ? 0 : newHeight;
    rgb.resize(static_cast<std::size_t>(width) * height * 3);
}

std::vector<std::uint8_t> encodePng(const Image& image) {
    if (image.width <= 0 || image.height <= 0 ||
        image.rgb.size() != static_cast<std::size_t>(image.width) * image.height * 3) {
        throw std::invalid_argument("encodePng: the image is empty or its size does not match its pixels");
    }
    int length = 0;
    unsigned char* png = stbi_write_png_to_mem(image.rgb.data(), image.width * 3, image.width, image.height, 3,
                                               &length);
    if (png == nullptr) throw std::runtime_error("encodePng: out of memory");
    std::vector<std::uint8_t> bytes(png, png + length);
    STBIW_FREE(png);
    return bytes;
}

void writeFileAtomically(const std::filesystem::path& path, const std::vector<std::uint8_t>& bytes) {
    // A name no other writer (thread or process) uses, hidden, in the same folder: rename()
    // within one file system replaces the target in one step.
    static std::atomic<unsigned> counter{0};
    char suffix[48];
    std::snprintf(suffix, sizeof suffix, ".%ld-%u.part", static_cast<long>(::getpid()), counter++);
    std::string name = '.' + path.filename().string() + suffix;
    std::filesystem::path temporary = path.parent_path() / name;

    std::FILE* file = std::fopen(temporary.c_str(), "wb");
    if (file == nullptr) {
        throw std::runtime_error("cannot write " + path.string() + ": " + reason(errno));
    }
    // An empty vector's data() may be null, which fwrite must not be given even for 0 bytes.
    bool written = bytes.empty() || std::fwrite(bytes.data(), 1, bytes.size(), file) == bytes.size();
    int writeError = errno;
    if (std::fclose(file) != 0 && written) {
        written = false;
        writeError = errno;
    }
    if (!written) {
        std::remove(temporary.c_str());
        throw std::runtime_error("cannot write " + path.string() + ": " + reason(writeError));
    }
    std::error_code error;
    std::filesystem::rename(temporary, path, error);
    if (error) {
        std::remove(temporary.c_str());
        throw std::runtime_error("cannot rename the finished file to " + path.string() + ": " + error.message());
    }
}

void writePng(const std::filesystem::path& path, const Image& image) { writeFileAtomically(path, encodePng(image)); }

Image readPng(const std::filesystem::path& path) {
    std::FILE* file = std::fopen(path.c_str(), "rb");
    if (file == nullptr) {
        throw std::runtime_error("cannot read " + path.string() + ": " + reason(errno));
    }
    int width = 0;
    int height = 0;
    int channels = 0;
    stbi_uc* pixels = stbi_load_from_file(file, &width, &height, &channels, 3);
    std::fclose(file);
    if (pixels == nullptr) {
        throw std::runtime_error("cannot decode " + path.string() + " as PNG: " + stbi_failure_reason());
    }
    Image image;
    image.width = width;
    image.height = height;
    image.rgb.assign(pixels, pixels + static_cast<std::size_t>(width) * height * 3);
    stbi_image_free(pixels);
    return image;
}

} // namespace rube::render

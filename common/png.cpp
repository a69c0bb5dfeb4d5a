#include "common/png.hpp"

#include "common/error.hpp"
#include "common/output.hpp"

#include <stb_image.h>
#include <stb_image_write.h>

#include <filesystem>
#include <memory>

namespace rt {

void write_png(const std::string& path, const Image& image)
{
    check_writable(path, "PNG");
    const std::vector<std::uint8_t> bytes = to_srgb8(image);
    // stb returns 0 on failure and non-0 on success.
    if (image.width < 1 || image.height < 1 ||
        stbi_write_png(path.c_str(), image.width, image.height, 3, bytes.data(), 3 * image.width) == 0)
        throw InputError(path + ": cannot write the PNG file");
}

std::vector<std::uint8_t> read_png_bytes(const std::string& path, int& width, int& height)
{
    int channels_in_file = 0;
    std::unique_ptr<unsigned char, void (*)(void*)> data(
        stbi_load(path.c_str(), &width, &height, &channels_in_file, 3), stbi_image_free);
    if (!data)
        throw InputError(path + ": cannot read the PNG file (" + stbi_failure_reason() + ")");
    return std::vector<std::uint8_t>(data.get(), data.get() + static_cast<size_t>(width) * height * 3);
}

Image read_png(const std::string& path)
{
    int width = 0, height = 0;
    const std::vector<std::uint8_t> bytes = read_png_bytes(path, width, height);
    return from_srgb8(bytes, width, height);
}

}  // namespace rt

// SPDX-License-Identifier: Zlib
#include <btFracture/io/PngFile.h>

#include <btFracture/core/Error.h>

#include <png.h>

#include <cstring>

namespace btfracture {

void writePng(const std::string& path, const Image& image) {
    if (image.empty()) throw Error("cannot write PNG '" + path + "': the image is empty");
    png_image info;
    std::memset(&info, 0, sizeof info);
    info.version = PNG_IMAGE_VERSION;
    info.width = static_cast<png_uint_32>(image.width());
    info.height = static_cast<png_uint_32>(image.height());
    info.format = PNG_FORMAT_RGB;
    info.flags = PNG_IMAGE_FLAG_FAST;  // speed over size: preview frames are written every few steps
    static_assert(sizeof(Rgb) == 3, "Rgb must be three packed bytes");
    if (!png_image_write_to_file(&info, path.c_str(), 0, image.pixels().data(), 0, nullptr)) {
        const std::string reason = info.message;
        png_image_free(&info);
        throw Error("cannot write PNG '" + path + "': " + reason);
    }
}

Image readPng(const std::string& path) {
    png_image info;
    std::memset(&info, 0, sizeof info);
    info.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&info, path.c_str()))
        throw Error("cannot read PNG '" + path + "': " + info.message);
    info.format = PNG_FORMAT_RGB;
    if (info.width < 1 || info.height < 1 || info.width > 16384 || info.height > 16384) {
        png_image_free(&info);
        throw Error("cannot read PNG '" + path + "': size " + std::to_string(info.width) + " x " +
                    std::to_string(info.height) + " outside [1, 16384]");
    }
    Image image(static_cast<int>(info.width), static_cast<int>(info.height));
    const png_color black{0, 0, 0};
    if (!png_image_finish_read(&info, &black, image.data(), 0, nullptr)) {
        const std::string reason = info.message;
        png_image_free(&info);
        throw Error("cannot read PNG '" + path + "': " + reason);
    }
    return image;
}

}  // namespace btfracture

// SPDX-License-Identifier: Zlib
#include <btFracture/io/PlyReader.h>

#include <btFracture/core/Error.h>
#include <btFracture/io/PolygonFan.h>
#include <btFracture/io/ReadFile.h>
#include <btFracture/io/TextTokens.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <sstream>

namespace btfracture {
namespace {

enum class Format { Ascii, BinaryLittleEndian, BinaryBigEndian };
enum class Type { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

struct Property {
    std::string name;
    Type type = Type::Float32;  // item type for lists
    bool isList = false;
    Type countType = Type::UInt8;
};

struct Element {
    std::string name;
    long long count = 0;
    std::vector<Property> properties;
};

bool parseType(std::string_view name, Type& type) {
    static const std::pair<const char*, Type> names[] = {
        {"char", Type::Int8},      {"int8", Type::Int8},       {"uchar", Type::UInt8},
        {"uint8", Type::UInt8},    {"short", Type::Int16},     {"int16", Type::Int16},
        {"ushort", Type::UInt16},  {"uint16", Type::UInt16},   {"int", Type::Int32},
        {"int32", Type::Int32},    {"uint", Type::UInt32},     {"uint32", Type::UInt32},
        {"float", Type::Float32},  {"float32", Type::Float32}, {"double", Type::Float64},
        {"float64", Type::Float64}};
    for (const auto& [text, value] : names)
        if (name == text) {
            type = value;
            return true;
        }
    return false;
}

bool isInteger(Type type) {
    return type != Type::Float32 && type != Type::Float64;
}

int sizeOf(Type type) {
    switch (type) {
        case Type::Int8:
        case Type::UInt8:
            return 1;
        case Type::Int16:
        case Type::UInt16:
            return 2;
        case Type::Int32:
        case Type::UInt32:
        case Type::Float32:
            return 4;
        case Type::Float64:
            return 8;
    }
    return 0;
}

struct Header {
    Format format = Format::Ascii;
    std::vector<Element> elements;
    size_t dataOffset = 0;  // first byte after end_header
    int dataLine = 0;       // line number of the first ascii data line
};

Header parseHeader(const std::string& bytes, const std::string& source) {
    LineReader lines(bytes);
    std::string_view line;
    std::vector<std::string_view> tokens;
    auto fail = [&](const std::string& problem) -> void {
        throw Error(source + ": header line " + std::to_string(lines.lineNumber()) + ": " + problem);
    };
    if (!lines.next(line) || line != "ply") fail("expected 'ply' as the first line (not a PLY file?)");
    Header header;
    bool haveFormat = false;
    while (true) {
        if (!lines.next(line)) fail("file ends before 'end_header'");
        splitTokens(line, tokens);
        if (tokens.empty()) continue;
        const std::string_view keyword = tokens[0];
        if (keyword == "comment" || keyword == "obj_info") continue;
        if (keyword == "end_header") break;
        if (keyword == "format") {
            if (tokens.size() != 3 || tokens[2] != "1.0")
                fail("expected 'format ascii|binary_little_endian|binary_big_endian 1.0', got '" +
                     std::string(line) + "'");
            if (tokens[1] == "ascii")
                header.format = Format::Ascii;
            else if (tokens[1] == "binary_little_endian")
                header.format = Format::BinaryLittleEndian;
            else if (tokens[1] == "binary_big_endian")
                header.format = Format::BinaryBigEndian;
            else
                fail("unknown PLY format '" + std::string(tokens[1]) + "'");
            haveFormat = true;
        } else if (keyword == "element") {
            long long count;
            if (tokens.size() != 3 || !parseInteger(tokens[2], count) || count < 0)
                fail("expected 'element <name> <count>', got '" + std::string(line) + "'");
            header.elements.push_back({std::string(tokens[1]), count, {}});
        } else if (keyword == "property") {
            if (header.elements.empty()) fail("'property' before any 'element'");
            Property p;
            if (tokens.size() == 5 && tokens[1] == "list") {
                Type countType, itemType;
                if (!parseType(tokens[2], countType) || !parseType(tokens[3], itemType))
                    fail("unknown type in '" + std::string(line) + "'");
                if (!isInteger(countType))
                    fail("list count type must be an integer type, got '" + std::string(tokens[2]) + "'");
                p = {std::string(tokens[4]), itemType, true, countType};
            } else if (tokens.size() == 3) {
                Type type;
                if (!parseType(tokens[1], type))
                    fail("unknown property type '" + std::string(tokens[1]) + "'");
                p = {std::string(tokens[2]), type, false, Type::UInt8};
            } else {
                fail(
                    "expected 'property <type> <name>' or 'property list <count type> <item type> <name>', "
                    "got '" +
                    std::string(line) + "'");
            }
            header.elements.back().properties.push_back(p);
        } else {
            fail("unknown header keyword '" + std::string(keyword) + "'");
        }
    }
    if (!haveFormat) fail("no 'format' line before 'end_header'");
    header.dataOffset = lines.offset();
    header.dataLine = lines.lineNumber() + 1;
    return header;
}

// Values of one element instance, read from ascii lines or binary bytes.
class ValueSource {
public:
    ValueSource(const std::string& bytes, const Header& header, const std::string& source)
        : bytes_(bytes),
          format_(header.format),
          position_(header.dataOffset),
          source_(source),
          lines_(std::string_view(bytes).substr(header.dataOffset)),
          firstLine_(header.dataLine) {}

    // Starts instance `index` of `element` (for ascii: its own line).
    void begin(const Element& element, long long index) {
        element_ = &element;
        index_ = index;
        if (format_ != Format::Ascii) return;
        std::string_view line;
        do {
            if (!lines_.next(line))
                fail("file ends early; expected " + std::to_string(element.count) + " " + element.name +
                     " lines");
            splitTokens(line, tokens_);
        } while (tokens_.empty());
        next_ = 0;
    }
    // Ascii only: every token of the line was used.
    void end() {
        if (format_ == Format::Ascii && next_ != tokens_.size())
            fail("expected " + std::to_string(next_) + " values on this line, got " +
                 std::to_string(tokens_.size()));
    }

    double number(Type type, const std::string& property) {
        if (format_ == Format::Ascii) {
            if (next_ >= tokens_.size()) fail("missing value for property '" + property + "'");
            const std::string_view token = tokens_[next_++];
            double value;
            long long integer;
            if (isInteger(type) ? !parseInteger(token, integer) : !parseDouble(token, value))
                fail("expected " + std::string(isInteger(type) ? "an integer" : "a number") +
                     " for property '" + property + "', got '" + std::string(token) + "'");
            return isInteger(type) ? static_cast<double>(integer) : value;
        }
        if (position_ + sizeOf(type) > bytes_.size()) fail("file ends early in property '" + property + "'");
        switch (type) {
            case Type::Int8:
                return take<int8_t>();
            case Type::UInt8:
                return take<uint8_t>();
            case Type::Int16:
                return take<int16_t>();
            case Type::UInt16:
                return take<uint16_t>();
            case Type::Int32:
                return take<int32_t>();
            case Type::UInt32:
                return take<uint32_t>();
            case Type::Float32:
                return take<float>();
            case Type::Float64:
                return take<double>();
        }
        return 0.0;
    }

    [[noreturn]] void fail(const std::string& problem) const {
        std::ostringstream msg;
        msg << source_;
        if (format_ == Format::Ascii) msg << ":" << firstLine_ + lines_.lineNumber() - 1;
        msg << ": " << element_->name << " " << index_ << ": " << problem;
        throw Error(msg.str());
    }

private:
    // The next binary value as T (its size fixed at compile time), bytes in the file's order.
    template <class T>
    double take() {
        unsigned char raw[sizeof(T)];
        std::memcpy(raw, bytes_.data() + position_, sizeof(T));
        position_ += sizeof(T);
        if (format_ == Format::BinaryBigEndian)
            std::reverse(raw, raw + sizeof(T));  // this machine: little endian
        T value;
        std::memcpy(&value, raw, sizeof(T));
        return static_cast<double>(value);
    }

    const std::string& bytes_;
    Format format_;
    size_t position_;
    const std::string& source_;
    LineReader lines_;
    int firstLine_;
    std::vector<std::string_view> tokens_;
    size_t next_ = 0;
    const Element* element_ = nullptr;
    long long index_ = 0;
};

int propertyIndex(const Element& element, const std::string& name) {
    for (size_t i = 0; i < element.properties.size(); ++i)
        if (element.properties[i].name == name) return static_cast<int>(i);
    return -1;
}

}  // namespace

TriangleMesh parsePly(const std::string& bytes, const std::string& source) {
    const Header header = parseHeader(bytes, source);
    const Element* vertexElement = nullptr;
    const Element* faceElement = nullptr;
    for (const auto& element : header.elements) {
        if (element.name == "vertex") vertexElement = &element;
        if (element.name == "face") faceElement = &element;
    }
    if (!vertexElement || !faceElement)
        throw Error(source + ": expected a 'vertex' and a 'face' element in the header");
    int xyz[3];
    for (int k = 0; k < 3; ++k) {
        const std::string name(1, "xyz"[k]);
        xyz[k] = propertyIndex(*vertexElement, name);
        if (xyz[k] < 0 || vertexElement->properties[xyz[k]].isList)
            throw Error(source + ": expected a scalar property '" + name + "' in element 'vertex'");
    }
    int indicesProperty = propertyIndex(*faceElement, "vertex_indices");
    if (indicesProperty < 0) indicesProperty = propertyIndex(*faceElement, "vertex_index");
    if (indicesProperty < 0 || !faceElement->properties[indicesProperty].isList ||
        !isInteger(faceElement->properties[indicesProperty].type))
        throw Error(source + ": expected an integer list property 'vertex_indices' in element 'face'");

    TriangleMesh mesh;
    mesh.name = source;
    PolygonFan fan(mesh);
    ValueSource values(bytes, header, source);
    std::vector<int> corners;
    for (const auto& element : header.elements) {
        for (long long i = 0; i < element.count; ++i) {
            values.begin(element, i);
            Eigen::Vector3d p = Eigen::Vector3d::Zero();
            corners.clear();
            for (size_t k = 0; k < element.properties.size(); ++k) {
                const Property& property = element.properties[k];
                if (!property.isList) {
                    const double value = values.number(property.type, property.name);
                    if (&element == vertexElement)
                        for (int c = 0; c < 3; ++c)
                            if (xyz[c] == static_cast<int>(k)) p[c] = value;
                    continue;
                }
                const double count = values.number(property.countType, property.name + " count");
                if (count < 0) values.fail("negative list length " + std::to_string(count));
                const bool isCorners = &element == faceElement && static_cast<int>(k) == indicesProperty;
                if (isCorners && count < 3)
                    values.fail("expected at least 3 vertex indices, got " +
                                std::to_string(static_cast<long long>(count)));
                for (long long item = 0; item < static_cast<long long>(count); ++item) {
                    const double index = values.number(property.type, property.name);
                    if (!isCorners) continue;
                    if (index < 0 || index >= static_cast<double>(vertexElement->count))
                        values.fail("vertex index " + std::to_string(static_cast<long long>(index)) +
                                    " out of range (" + std::to_string(vertexElement->count) + " vertices)");
                    corners.push_back(static_cast<int>(index));
                }
            }
            values.end();
            if (&element == vertexElement) mesh.vertices.push_back(p);
            if (&element == faceElement) fan.add(corners);
        }
    }
    fan.report(source);
    return mesh;
}

TriangleMesh readPly(const std::string& path) {
    return parsePly(readWholeFile(path, "mesh file"), path);
}

}  // namespace btfracture

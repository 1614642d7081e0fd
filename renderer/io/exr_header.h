#pragma once
// The header of a single-part scan-line OpenEXR file, made and written by
// raylab: the attributes OpenEXR's Imf::Header holds for such a file, and
// their bytes exactly as Imf::Header::writeTo writes them (the attributes in
// name order, each as name, type name, size and value; the channel list
// sorted by name; a zero byte after the last).
//
// Why not Imf::Header: the ZIP and ZIPS files raylab writes (its default
// output) are raylab's bytes already, blocks and offset table
// (exr_zip_file.h); the header is the last part that needs OpenEXR, whose
// libraries cost 2.3-2.9 ms of every process's start-up on this project's
// VMs (docs/benchmarks.md, session 2026-12-06 08:45). The other compressions
// give its attributes to OpenEXR's module (exr_module.h), so both paths start
// from one header. tests/output/test_exr_header.cpp compares the bytes with
// Imf::Header::writeTo's.

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace raylab {

/// OpenEXR's pixel types, with the file format's numbers.
enum class ExrPixelType : int32_t { Uint = 0, Half = 1, Float = 2 };

/// Bytes per value of a channel of this type (HALF 2; FLOAT and UINT 4).
size_t exrPixelTypeSize(ExrPixelType type);

/// OpenEXR's compression methods raylab writes, with the file format's numbers.
enum class ExrCompressionId : uint8_t { None = 0, Rle = 1, Zips = 2, Zip = 3, Piz = 4 };

/// Scan lines of one block (chunk) of a file with this compression (OpenEXR's rule).
int exrLinesPerBlock(ExrCompressionId compression);

/// One attribute of a header: its name, its type's name and its value's bytes.
struct ExrAttribute {
    std::string name;
    std::string typeName;
    std::string value;
};

/// An integer box, corners inclusive (OpenEXR's box2i).
struct ExrBox {
    int32_t xMin = 0, yMin = 0, xMax = -1, yMax = -1;
    int32_t width() const { return xMax - xMin + 1; }
    int32_t height() const { return yMax - yMin + 1; }
};

class ExrHeader {
public:
    /// The attributes every file has, with Imf::Header's defaults: pixel aspect
    /// ratio 1, screen window centre (0, 0) and width 1, increasing-y line
    /// order, ZIP compression, no channel.
    ExrHeader(const ExrBox& displayWindow, const ExrBox& dataWindow);

    void setCompression(ExrCompressionId compression);
    ExrCompressionId compression() const { return m_compression; }
    const ExrBox& dataWindow() const { return m_dataWindow; }

    /// Adds (or retypes) a channel, full resolution (sampling 1 x 1), not
    /// perceptually linear.
    void addChannel(const std::string& name, ExrPixelType type);
    struct Channel {
        std::string name;
        ExrPixelType type;
    };
    /// The channels in the file's order (sorted by name).
    std::vector<Channel> channels() const;

    /// Adds or replaces an attribute of type "string", "int" or "m44f"
    /// (a row-major 4 x 4 float matrix, Imath's M44f).
    void setString(const std::string& name, const std::string& value);
    void setInt(const std::string& name, int32_t value);
    void setM44f(const std::string& name, const float (&m)[4][4]);
    /// Adds or replaces an attribute of any type, given its value's bytes.
    void setAttribute(const std::string& name, const std::string& typeName, std::string value);

    /// Every attribute but the channel list (channels()), in name order.
    std::vector<ExrAttribute> attributes() const;

    /// Whether a name reaches 32 characters: the version field then carries
    /// the long-names flag (OpenEXR's rule, ImfHeader.cpp).
    bool usesLongNames() const;
    /// The file's version field: 2, with the long-names flag (0x400) when
    /// usesLongNames().
    int32_t versionField() const { return 2 | (usesLongNames() ? 0x400 : 0); }

    /// Appends the header's bytes, as Imf::Header::writeTo writes them (after
    /// the magic number and version field, which are not the header's).
    void appendTo(std::string& out) const;

private:
    struct Attribute {
        std::string typeName;
        std::string value;
    };
    ExrBox m_dataWindow;
    ExrCompressionId m_compression = ExrCompressionId::Zip;
    std::map<std::string, ExrPixelType> m_channels;  ///< by name: the file's order
    std::map<std::string, Attribute> m_attributes;   ///< all but "channels", by name
};

}  // namespace raylab

#include "renderer/io/exr_header.h"

#include <cstring>
#include <stdexcept>

namespace raylab {

namespace {

/// EXR's numbers are little-endian, as is every CPU raylab builds for.
static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "EXR bytes are written as in memory");

template <typename T>
void append(std::string& out, T v) {
    out.append(reinterpret_cast<const char*>(&v), sizeof v);
}

/// A name as the file holds it: its characters and a zero byte.
void appendName(std::string& out, const std::string& name) {
    out.append(name);
    out.push_back('\0');
}

std::string boxBytes(const ExrBox& b) {
    std::string v;
    for (int32_t x : {b.xMin, b.yMin, b.xMax, b.yMax}) append(v, x);
    return v;
}

/// Names a file cannot hold: OpenEXR reads names up to 255 characters, and a
/// zero byte would end one early.
void checkName(const std::string& name, const char* what) {
    if (name.empty() || name.size() > 255 || name.find('\0') != std::string::npos)
        throw std::invalid_argument(std::string("EXR ") + what + " name '" + name +
                                    "' is empty, longer than 255 characters or holds a zero byte");
}

}  // namespace

size_t exrPixelTypeSize(ExrPixelType type) { return type == ExrPixelType::Half ? 2 : 4; }

int exrLinesPerBlock(ExrCompressionId compression) {
    switch (compression) {
        case ExrCompressionId::None:
        case ExrCompressionId::Rle:
        case ExrCompressionId::Zips: return 1;
        case ExrCompressionId::Zip: return 16;
        case ExrCompressionId::Piz: return 32;
    }
    return 1;
}

ExrHeader::ExrHeader(const ExrBox& displayWindow, const ExrBox& dataWindow)
    : m_dataWindow(dataWindow) {
    if (displayWindow.width() <= 0 || displayWindow.height() <= 0 || dataWindow.width() <= 0 ||
        dataWindow.height() <= 0)
        throw std::invalid_argument("EXR header: an empty display or data window");
    setAttribute("displayWindow", "box2i", boxBytes(displayWindow));
    setAttribute("dataWindow", "box2i", boxBytes(dataWindow));
    std::string v;
    append(v, 1.0f);
    setAttribute("pixelAspectRatio", "float", v);
    v.clear();
    append(v, 0.0f);
    append(v, 0.0f);
    setAttribute("screenWindowCenter", "v2f", v);
    v.clear();
    append(v, 1.0f);
    setAttribute("screenWindowWidth", "float", v);
    setAttribute("lineOrder", "lineOrder", std::string(1, '\0'));  // INCREASING_Y
    setCompression(ExrCompressionId::Zip);
}

void ExrHeader::setCompression(ExrCompressionId compression) {
    m_compression = compression;
    setAttribute("compression", "compression", std::string(1, char(compression)));
}

void ExrHeader::addChannel(const std::string& name, ExrPixelType type) {
    checkName(name, "channel");
    m_channels[name] = type;
}

std::vector<ExrHeader::Channel> ExrHeader::channels() const {
    std::vector<Channel> out;
    out.reserve(m_channels.size());
    for (const auto& [name, type] : m_channels) out.push_back({name, type});
    return out;
}

void ExrHeader::setString(const std::string& name, const std::string& value) {
    setAttribute(name, "string", value);
}

void ExrHeader::setInt(const std::string& name, int32_t value) {
    std::string v;
    append(v, value);
    setAttribute(name, "int", v);
}

void ExrHeader::setM44f(const std::string& name, const float (&m)[4][4]) {
    std::string v;
    for (const auto& row : m)
        for (float x : row) append(v, x);
    setAttribute(name, "m44f", v);
}

void ExrHeader::setAttribute(const std::string& name, const std::string& typeName,
                             std::string value) {
    checkName(name, "attribute");
    checkName(typeName, "attribute type");
    if (name == "channels")  // the channel list is made from addChannel
        throw std::invalid_argument("EXR header: 'channels' is set by addChannel");
    if (value.size() > size_t(INT32_MAX))
        throw std::invalid_argument("EXR attribute '" + name + "' is larger than 2 GiB");
    m_attributes[name] = Attribute{typeName, std::move(value)};
}

std::vector<ExrAttribute> ExrHeader::attributes() const {
    std::vector<ExrAttribute> out;
    out.reserve(m_attributes.size());
    for (const auto& [name, a] : m_attributes) out.push_back({name, a.typeName, a.value});
    return out;
}

bool ExrHeader::usesLongNames() const {
    for (const auto& [name, a] : m_attributes)
        if (name.size() >= 32 || a.typeName.size() >= 32) return true;
    for (const auto& [name, type] : m_channels)
        if (name.size() >= 32) return true;
    return false;
}

void ExrHeader::appendTo(std::string& out) const {
    // Each channel: name, pixel type, pLinear and three reserved bytes, x and
    // y sampling; a zero byte after the last (ImfChannelListAttribute.cpp).
    std::string channelList;
    for (const auto& [name, type] : m_channels) {
        appendName(channelList, name);
        append(channelList, int32_t(type));
        append(channelList, uint32_t(0));  // pLinear 0, reserved 0 0 0
        append(channelList, int32_t(1));
        append(channelList, int32_t(1));
    }
    channelList.push_back('\0');

    size_t size = 1 + channelList.size() + 32;
    for (const auto& [name, a] : m_attributes) size += name.size() + a.typeName.size() + 6 + a.value.size();
    out.reserve(out.size() + size);
    const auto write = [&](const std::string& name, const std::string& typeName,
                           const std::string& value) {
        appendName(out, name);
        appendName(out, typeName);
        append(out, int32_t(value.size()));
        out.append(value);
    };
    // "channels" sorts first among the attributes raylab writes, but any
    // name before it ("Channels", "aperture", ...) goes first, as in the map
    // Imf::Header keeps.
    bool channelsWritten = false;
    for (const auto& [name, a] : m_attributes) {
        if (!channelsWritten && name > "channels") {
            write("channels", "chlist", channelList);
            channelsWritten = true;
        }
        write(name, a.typeName, a.value);
    }
    if (!channelsWritten) write("channels", "chlist", channelList);
    out.push_back('\0');
}

}  // namespace raylab

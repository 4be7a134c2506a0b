// A run page's bytes: zlib as a browser's DecompressionStream reads it, the referee's PNG packed
// smaller, and the player's script deflated (run_page.hpp).
#include "aula/grade/run_page.hpp"

#include "player_assets.hpp"

#include <QBuffer>
#include <QByteArray>
#include <QImage>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace aula::grade {

std::string deflated(const std::string& bytes) {
  QByteArray packed = qCompress(QByteArray(bytes.data(), static_cast<int>(bytes.size())), 9);
  packed.remove(0, 4);  // qCompress's length prefix: the rest is a zlib stream ("deflate" to a browser)
  return packed.toStdString();
}

std::string inflated(const std::string& zlib) {
  if (zlib.size() < 6) return "";
  // qUncompress wants qCompress's 4-byte length first: a guess is enough (it grows its buffer).
  const uint32_t guess = static_cast<uint32_t>(std::min<size_t>(zlib.size() * 8, 64u << 20));
  QByteArray framed;
  for (int shift : {24, 16, 8, 0}) framed.append(static_cast<char>((guess >> shift) & 0xff));
  framed.append(zlib.data(), static_cast<int>(zlib.size()));
  const QByteArray out = qUncompress(framed);
  return std::string(out.constData(), static_cast<size_t>(out.size()));
}

namespace {

uint32_t crc32Of(const std::string& bytes) {  // PNG's CRC (ISO 3309)
  uint32_t crc = 0xffffffffu;
  for (unsigned char byte : bytes) {
    crc ^= byte;
    for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
  }
  return crc ^ 0xffffffffu;
}

std::string bigEndian(uint32_t value) {
  std::string out;
  for (int shift : {24, 16, 8, 0}) out += static_cast<char>((value >> shift) & 0xff);
  return out;
}

}  // namespace

std::string smallerPng(const std::string& png) {
  static const std::string kSignature("\x89PNG\r\n\x1a\n", 8);
  if (png.compare(0, 8, kSignature) != 0) return png;
  std::string before, after, idat;  // the chunks before the first IDAT and after the last one
  bool seen = false;
  for (size_t at = 8; at + 12 <= png.size();) {
    const auto byte = [&](size_t i) { return static_cast<uint32_t>(static_cast<unsigned char>(png[i])); };
    const uint32_t length = (byte(at) << 24) | (byte(at + 1) << 16) | (byte(at + 2) << 8) | byte(at + 3);
    if (length > png.size() - at - 12) return png;  // cut short: left as it is
    const std::string type = png.substr(at + 4, 4);
    const std::string chunk = png.substr(at, 12 + length);
    if (type == "IDAT") {
      if (seen && !after.empty()) return png;  // IDATs not in a row: not a PNG to touch
      idat += png.substr(at + 8, length);
      seen = true;
    } else {
      (seen ? after : before) += chunk;
    }
    at += 12 + length;
  }
  const std::string pixels = inflated(idat);
  if (!seen || pixels.empty()) return png;
  const std::string packed = deflated(pixels);  // the same filtered rows, zlib's level 9
  const std::string chunk = "IDAT" + packed;
  const std::string out = kSignature + before + bigEndian(static_cast<uint32_t>(packed.size())) + chunk +
                          bigEndian(crc32Of(chunk)) + after;
  return out.size() < png.size() ? out : png;
}

std::string palettePng(const std::string& png) {
  QImage image;
  if (!image.loadFromData(reinterpret_cast<const uchar*>(png.data()), static_cast<int>(png.size()), "PNG") || image.hasAlphaChannel()) {
    return png;
  }
  image = image.convertToFormat(QImage::Format_RGB32);
  std::map<QRgb, size_t> counts;
  for (int y = 0; y < image.height(); ++y) {
    const auto* row = reinterpret_cast<const QRgb*>(image.constScanLine(y));
    for (int x = 0; x < image.width(); ++x) ++counts[row[x]];
  }
  // The most frequent first, ties by value: the same picture gives the same palette.
  std::vector<std::pair<size_t, QRgb>> by_count;
  for (const auto& [colour, n] : counts) by_count.push_back({n, colour});
  std::sort(by_count.begin(), by_count.end(), [](const auto& a, const auto& b) { return a.first != b.first ? a.first > b.first : a.second < b.second; });
  QVector<QRgb> table;
  for (size_t i = 0; i < by_count.size() && i < 256; ++i) table.push_back(by_count[i].second);
  const QImage indexed = image.convertToFormat(QImage::Format_Indexed8, table, Qt::ThresholdDither | Qt::AvoidDither);
  QByteArray bytes;
  QBuffer buffer(&bytes);
  buffer.open(QIODevice::WriteOnly);
  if (!indexed.save(&buffer, "PNG")) return png;
  const std::string out = smallerPng(bytes.toStdString());
  return out.size() < png.size() ? out : png;
}

std::string urlPath(const std::string& path) {
  static const char* hex = "0123456789ABCDEF";
  std::string out;
  for (unsigned char c : path) {
    if (std::isalnum(c) || std::string("/-_.~").find(static_cast<char>(c)) != std::string::npos) {
      out += static_cast<char>(c);
    } else {
      out += '%';
      out += hex[c >> 4];
      out += hex[c & 15];
    }
  }
  return out;
}

std::string packedPlayerScript() {
  static const std::string packed = QByteArray::fromStdString(deflated(kPlayerScriptJs)).toBase64().toStdString();
  return packed;
}

}  // namespace aula::grade

#include "camera/exif.h"

#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <memory>
#include <sstream>

#include <libexif/exif-data.h>
#include <libexif/exif-format.h>
#include <libexif/exif-mem.h>
#include <libexif/exif-utils.h>

#include "core/common/error.h"

namespace rockface::camera {

bool ExifInfo::empty() const {
  return make.empty() && model.empty() && lens.empty() && serial.empty() && datetime.empty() &&
         !focal_length_mm && !f_number && !exposure_time_s && !iso && !flash_fired &&
         !focus_distance_m && !width && !height;
}

namespace {

struct ExifDataDeleter {
  void operator()(ExifData* d) const { exif_data_unref(d); }
};
using ExifDataPtr = std::unique_ptr<ExifData, ExifDataDeleter>;

// A rational with a zero denominator or a wrong format is not a value.
std::optional<double> rational(ExifEntry* e, ExifByteOrder order) {
  if (!e || e->components < 1 || !e->data) return std::nullopt;
  if (e->format == EXIF_FORMAT_RATIONAL && e->size >= 8) {
    const ExifRational r = exif_get_rational(e->data, order);
    if (r.denominator == 0) return std::nullopt;
    return static_cast<double>(r.numerator) / r.denominator;
  }
  if (e->format == EXIF_FORMAT_SRATIONAL && e->size >= 8) {
    const ExifSRational r = exif_get_srational(e->data, order);
    if (r.denominator == 0) return std::nullopt;
    return static_cast<double>(r.numerator) / r.denominator;
  }
  return std::nullopt;
}

std::optional<int> integer(ExifEntry* e, ExifByteOrder order) {
  if (!e || e->components < 1 || !e->data) return std::nullopt;
  if (e->format == EXIF_FORMAT_SHORT && e->size >= 2) return exif_get_short(e->data, order);
  if (e->format == EXIF_FORMAT_LONG && e->size >= 4)
    return static_cast<int>(exif_get_long(e->data, order));
  return std::nullopt;
}

std::string ascii(ExifEntry* e) {
  if (!e || e->format != EXIF_FORMAT_ASCII || !e->data) return {};
  std::string s(reinterpret_cast<const char*>(e->data), e->size);
  s = s.substr(0, s.find('\0'));
  while (!s.empty() && s.back() == ' ') s.pop_back();
  return s;
}

ExifEntry* entry(ExifData* d, ExifIfd ifd, ExifTag tag) {
  return exif_content_get_entry(d->ifd[ifd], tag);
}

}  // namespace

ExifInfo read_exif(const std::vector<uint8_t>& jpeg) {
  ExifInfo info;
  if (jpeg.empty()) return info;
  ExifDataPtr d(exif_data_new_from_data(jpeg.data(), static_cast<unsigned int>(jpeg.size())));
  if (!d) return info;
  const ExifByteOrder order = exif_data_get_byte_order(d.get());
  info.make = ascii(entry(d.get(), EXIF_IFD_0, EXIF_TAG_MAKE));
  info.model = ascii(entry(d.get(), EXIF_IFD_0, EXIF_TAG_MODEL));
  info.lens = ascii(entry(d.get(), EXIF_IFD_EXIF, EXIF_TAG_LENS_MODEL));
  info.serial = ascii(entry(d.get(), EXIF_IFD_EXIF, EXIF_TAG_BODY_SERIAL_NUMBER));
  info.datetime = ascii(entry(d.get(), EXIF_IFD_EXIF, EXIF_TAG_DATE_TIME_ORIGINAL));
  if (info.datetime.empty()) info.datetime = ascii(entry(d.get(), EXIF_IFD_0, EXIF_TAG_DATE_TIME));
  info.focal_length_mm = rational(entry(d.get(), EXIF_IFD_EXIF, EXIF_TAG_FOCAL_LENGTH), order);
  info.f_number = rational(entry(d.get(), EXIF_IFD_EXIF, EXIF_TAG_FNUMBER), order);
  info.exposure_time_s = rational(entry(d.get(), EXIF_IFD_EXIF, EXIF_TAG_EXPOSURE_TIME), order);
  info.iso = integer(entry(d.get(), EXIF_IFD_EXIF, EXIF_TAG_ISO_SPEED_RATINGS), order);
  if (auto flash = integer(entry(d.get(), EXIF_IFD_EXIF, EXIF_TAG_FLASH), order))
    info.flash_fired = (*flash & 1) != 0;  // bit 0: flash fired
  info.focus_distance_m = rational(entry(d.get(), EXIF_IFD_EXIF, EXIF_TAG_SUBJECT_DISTANCE), order);
  info.width = integer(entry(d.get(), EXIF_IFD_EXIF, EXIF_TAG_PIXEL_X_DIMENSION), order);
  info.height = integer(entry(d.get(), EXIF_IFD_EXIF, EXIF_TAG_PIXEL_Y_DIMENSION), order);
  // Out-of-range values come from damaged blocks: drop them.
  auto positive = [](std::optional<double>& v) {
    if (v && !(std::isfinite(*v) && *v > 0)) v.reset();
  };
  positive(info.focal_length_mm);
  positive(info.f_number);
  positive(info.exposure_time_s);
  return info;
}

ExifInfo read_exif_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "cannot be opened");
  std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)),
                             std::istreambuf_iterator<char>());
  if (in.bad()) throw InputError(path, "read error");
  return read_exif(bytes);
}

namespace {

// An entry of the given format with zeroed data, owned by the IFD. Made by
// hand rather than by exif_entry_initialize, which knows default formats
// only for some tags.
ExifEntry* new_entry(ExifData* d, ExifIfd ifd, ExifTag tag, ExifFormat format,
                     unsigned long components) {
  ExifEntry* e = exif_entry_new();
  e->tag = tag;
  e->format = format;
  e->components = components;
  e->size = static_cast<unsigned int>(exif_format_get_size(format) * components);
  ExifMem* mem = exif_mem_new_default();
  e->data = static_cast<unsigned char*>(exif_mem_alloc(mem, e->size));
  exif_mem_unref(mem);
  std::memset(e->data, 0, e->size);
  exif_content_add_entry(d->ifd[ifd], e);
  exif_entry_unref(e);  // the IFD holds it now
  return e;
}

void set_ascii(ExifData* d, ExifIfd ifd, ExifTag tag, const std::string& text) {
  if (text.empty()) return;
  ExifEntry* e = new_entry(d, ifd, tag, EXIF_FORMAT_ASCII, text.size() + 1);
  std::memcpy(e->data, text.c_str(), text.size() + 1);
}

// Rationals over 10^6 (10^3 above 4000, to fit 32 bits): exact for
// exposure times such as 1/8000 s and far finer than any lens setting.
void set_rational(ExifData* d, ExifTag tag, double value, ExifByteOrder order) {
  ExifEntry* e = new_entry(d, EXIF_IFD_EXIF, tag, EXIF_FORMAT_RATIONAL, 1);
  ExifRational r;
  r.denominator = value < 4000 ? 1000000 : 1000;
  r.numerator = static_cast<ExifLong>(std::llround(value * r.denominator));
  exif_set_rational(e->data, order, r);
}

void set_short(ExifData* d, ExifIfd ifd, ExifTag tag, int value, ExifByteOrder order) {
  ExifEntry* e = new_entry(d, ifd, tag, EXIF_FORMAT_SHORT, 1);
  exif_set_short(e->data, order, static_cast<ExifShort>(value));
}

void set_long(ExifData* d, ExifIfd ifd, ExifTag tag, long value, ExifByteOrder order) {
  ExifEntry* e = new_entry(d, ifd, tag, EXIF_FORMAT_LONG, 1);
  exif_set_long(e->data, order, static_cast<ExifLong>(value));
}

}  // namespace

std::vector<uint8_t> with_exif(const std::vector<uint8_t>& jpeg, const ExifInfo& info) {
  if (jpeg.size() < 4 || jpeg[0] != 0xFF || jpeg[1] != 0xD8)
    throw Error("cannot add EXIF: the data is not a JPEG image");
  ExifDataPtr d(exif_data_new());
  const ExifByteOrder order = EXIF_BYTE_ORDER_INTEL;
  exif_data_set_byte_order(d.get(), order);
  exif_data_set_data_type(d.get(), EXIF_DATA_TYPE_COMPRESSED);
  set_ascii(d.get(), EXIF_IFD_0, EXIF_TAG_MAKE, info.make);
  set_ascii(d.get(), EXIF_IFD_0, EXIF_TAG_MODEL, info.model);
  set_ascii(d.get(), EXIF_IFD_EXIF, EXIF_TAG_LENS_MODEL, info.lens);
  set_ascii(d.get(), EXIF_IFD_EXIF, EXIF_TAG_BODY_SERIAL_NUMBER, info.serial);
  set_ascii(d.get(), EXIF_IFD_EXIF, EXIF_TAG_DATE_TIME_ORIGINAL, info.datetime);
  if (info.focal_length_mm)
    set_rational(d.get(), EXIF_TAG_FOCAL_LENGTH, *info.focal_length_mm, order);
  if (info.f_number) set_rational(d.get(), EXIF_TAG_FNUMBER, *info.f_number, order);
  if (info.exposure_time_s)
    set_rational(d.get(), EXIF_TAG_EXPOSURE_TIME, *info.exposure_time_s, order);
  if (info.focus_distance_m)
    set_rational(d.get(), EXIF_TAG_SUBJECT_DISTANCE, *info.focus_distance_m, order);
  if (info.iso) set_short(d.get(), EXIF_IFD_EXIF, EXIF_TAG_ISO_SPEED_RATINGS, *info.iso, order);
  // Flash value 0x10: "flash did not fire, compulsory flash suppression"; 0x01: fired.
  if (info.flash_fired)
    set_short(d.get(), EXIF_IFD_EXIF, EXIF_TAG_FLASH, *info.flash_fired ? 0x01 : 0x10, order);
  if (info.width) set_long(d.get(), EXIF_IFD_EXIF, EXIF_TAG_PIXEL_X_DIMENSION, *info.width, order);
  if (info.height)
    set_long(d.get(), EXIF_IFD_EXIF, EXIF_TAG_PIXEL_Y_DIMENSION, *info.height, order);

  unsigned char* block = nullptr;
  unsigned int size = 0;
  exif_data_save_data(d.get(), &block, &size);
  std::unique_ptr<unsigned char, void (*)(void*)> owned(block, free);
  if (!block || size + 2 > 0xFFFF) throw Error("cannot add EXIF: the EXIF block is too large");

  // Copy the JPEG, dropping any APP1 EXIF segment, with ours after SOI.
  std::vector<uint8_t> out;
  out.reserve(jpeg.size() + size + 6);
  for (const unsigned marker : {0xFFu, 0xD8u, 0xFFu, 0xE1u, (size + 2) >> 8, (size + 2) & 0xFFu})
    out.push_back(static_cast<uint8_t>(marker));
  out.insert(out.end(), block, block + size);
  size_t pos = 2;
  while (pos + 4 <= jpeg.size() && jpeg[pos] == 0xFF && jpeg[pos + 1] != 0xDA) {
    const size_t length = (static_cast<size_t>(jpeg[pos + 2]) << 8) | jpeg[pos + 3];
    if (pos + 2 + length > jpeg.size()) break;
    const bool is_exif =
        jpeg[pos + 1] == 0xE1 && length >= 8 && std::memcmp(&jpeg[pos + 4], "Exif\0\0", 6) == 0;
    if (!is_exif) out.insert(out.end(), jpeg.begin() + pos, jpeg.begin() + pos + 2 + length);
    pos += 2 + length;
  }
  out.insert(out.end(), jpeg.begin() + pos, jpeg.end());
  return out;
}

photogrammetry::PhotoCamera photo_camera(const ExifInfo& e) {
  photogrammetry::PhotoCamera c;
  c.make = e.make;
  c.model = e.model;
  c.serial = e.serial;
  c.lens = e.lens;
  c.focal_mm = e.focal_length_mm;
  c.width = e.width.value_or(0);
  c.height = e.height.value_or(0);
  return c;
}

std::map<std::string, std::string> exif_fields(const ExifInfo& e) {
  std::map<std::string, std::string> m;
  auto put = [&](const char* k, const auto& v) {
    if (v) {
      std::ostringstream s;
      s << *v;
      m[k] = s.str();
    }
  };
  if (!e.make.empty()) m["make"] = e.make;
  if (!e.model.empty()) m["model"] = e.model;
  if (!e.lens.empty()) m["lens"] = e.lens;
  if (!e.serial.empty()) m["serial"] = e.serial;
  if (!e.datetime.empty()) m["datetime"] = e.datetime;
  put("focal_length_mm", e.focal_length_mm);
  put("f_number", e.f_number);
  put("exposure_time_s", e.exposure_time_s);
  put("iso", e.iso);
  put("flash_fired", e.flash_fired);
  put("focus_distance_m", e.focus_distance_m);
  return m;
}

}  // namespace rockface::camera

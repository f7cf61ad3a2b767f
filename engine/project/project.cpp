#include "project/project.h"

#include "core/atomic_file.h"
#include "core/errors.h"
#include "core/format.h"
#include "project/byte_stream.h"
#include "project/content_checks.h"

#include <zlib.h> // for deflate, inflate, crc32

#include <algorithm>  // for std::min
#include <cerrno>     // for errno
#include <cstdio>     // for std::FILE, std::fopen, std::fread
#include <cstring>    // for std::memcmp, std::strerror
#include <filesystem> // for std::filesystem::path
#include <memory>     // for std::unique_ptr

namespace meshpaint {
namespace {

// The header: magic (8), version, header bytes, payload bytes (compressed),
// raw payload bytes, payload CRC-32, header CRC-32 (of the bytes before it).
constexpr unsigned char kMagic[8] = {0x89, 'M', 'P', 'R', 'O', 'J', '\r', '\n'};
constexpr std::size_t kHeaderBytes = 40;
// Bounds a damaged header cannot push a reader past.
constexpr std::uint64_t kMaxRawBytes = std::uint64_t(1) << 40;
// Deflate codes at best 258 bytes in 2 bits: a payload can never decompress
// to more than about 1032 times its size (plus the stream's few bytes of
// framing), so a header stating more is refused before anything is allocated.
constexpr std::uint64_t kMaxDeflateRatio = 1032;
constexpr std::uint64_t kDeflateFramingBytes = 64;

std::uint32_t crc_of(const unsigned char* data, std::size_t size)
{
  uLong crc = crc32(0L, Z_NULL, 0);
  while (size > 0) {
    const uInt chunk = uInt(std::min<std::size_t>(size, 1u << 30));
    crc = crc32(crc, data, chunk);
    data += chunk;
    size -= chunk;
  }
  return std::uint32_t(crc);
}

std::vector<unsigned char> deflated(std::vector<unsigned char>& raw)
{
  z_stream z{};
  if (deflateInit(&z, Z_BEST_SPEED) != Z_OK)
    throw IOError("cannot start zlib compression");
  std::vector<unsigned char> out(std::size_t(deflateBound(&z, uLong(raw.size()))));
  z.next_in = raw.data();
  z.avail_in = uInt(0);
  z.next_out = out.data();
  std::size_t in_left = raw.size(), out_left = out.size();
  int status = Z_OK;
  while (status != Z_STREAM_END) {
    // zlib counts in uInt: feed and drain at most 1 GiB at a time.
    if (z.avail_in == 0) {
      z.avail_in = uInt(std::min<std::size_t>(in_left, 1u << 30));
      in_left -= z.avail_in;
    }
    if (z.avail_out == 0) {
      z.avail_out = uInt(std::min<std::size_t>(out_left, 1u << 30));
      out_left -= z.avail_out;
    }
    status = deflate(&z, in_left == 0 ? Z_FINISH : Z_NO_FLUSH);
    if (status != Z_OK && status != Z_STREAM_END && status != Z_BUF_ERROR) {
      deflateEnd(&z);
      throw IOError("zlib compression failed");
    }
  }
  out.resize(out.size() - out_left - z.avail_out);
  deflateEnd(&z);
  return out;
}

std::vector<unsigned char> inflated(const std::vector<unsigned char>& packed, std::size_t raw_bytes,
                                    const std::string& where)
{
  std::vector<unsigned char> raw(raw_bytes);
  z_stream z{};
  if (inflateInit(&z) != Z_OK)
    throw IOError("cannot start zlib decompression");
  z.next_in = const_cast<unsigned char*>(packed.data());
  z.next_out = raw.data();
  std::size_t in_left = packed.size(), out_left = raw.size();
  int status = Z_OK;
  while (status == Z_OK) {
    if (z.avail_in == 0 && in_left > 0) {
      z.avail_in = uInt(std::min<std::size_t>(in_left, 1u << 30));
      in_left -= z.avail_in;
    }
    if (z.avail_out == 0 && out_left > 0) {
      z.avail_out = uInt(std::min<std::size_t>(out_left, 1u << 30));
      out_left -= z.avail_out;
    }
    status = inflate(&z, Z_NO_FLUSH);
  }
  const bool complete = status == Z_STREAM_END && out_left == 0 && z.avail_out == 0;
  inflateEnd(&z);
  if (!complete)
    throw InputError(where + ": corrupt project (payload does not decompress to its stated size)");
  return raw;
}

void put_u32(unsigned char* p, std::uint32_t v)
{
  for (int k = 0; k < 4; ++k)
    p[k] = (unsigned char)(v >> (8 * k));
}

void put_u64(unsigned char* p, std::uint64_t v)
{
  for (int k = 0; k < 8; ++k)
    p[k] = (unsigned char)(v >> (8 * k));
}

std::uint32_t get_u32(const unsigned char* p)
{
  std::uint32_t v = 0;
  for (int k = 0; k < 4; ++k)
    v |= std::uint32_t(p[k]) << (8 * k);
  return v;
}

std::uint64_t get_u64(const unsigned char* p)
{
  std::uint64_t v = 0;
  for (int k = 0; k < 8; ++k)
    v |= std::uint64_t(p[k]) << (8 * k);
  return v;
}

void write_payload(const Project& p, ByteWriter& w)
{
  w.begin_section("MESH");
  w.string(p.mesh.name);
  w.u32(std::uint32_t(p.mesh.points.size()));
  for (const Vec3& v : p.mesh.points)
    w.floats(v.data(), 3);
  w.u32(std::uint32_t(p.mesh.face_sizes.size()));
  for (const int n : p.mesh.face_sizes)
    w.u32(std::uint32_t(n));
  w.u32(std::uint32_t(p.mesh.face_vertices.size()));
  for (const int v : p.mesh.face_vertices)
    w.u32(std::uint32_t(v));
  w.end_section();

  w.begin_section("ATLS");
  w.u32(std::uint32_t(p.level));
  w.u64(p.positions.size());
  w.texels(p.positions);
  w.end_section();
  for (const auto& [tag, layer] : {std::pair{"DIFF", &p.channels.diffuse}, std::pair{"SPEC", &p.channels.specular},
                                   std::pair{"MATL", &p.channels.material}}) {
    if (layer->size() != p.positions.size())
      throw InputError("cannot save a project whose channels and positions differ in size");
    w.begin_section(tag);
    w.texels(*layer);
    w.end_section();
  }

  w.begin_section("REFP");
  if (!p.reference.empty() && p.reference.size() != p.positions.size())
    throw InputError("cannot save a project whose reference and positions differ in size");
  w.u64(p.reference.size());
  w.texels(p.reference);
  w.end_section();

  // Two-sided surfaces: the inside's layers, or none.
  w.begin_section("SIDE");
  const bool two_sided = !p.channels.inside_diffuse.empty();
  w.u32(two_sided ? 1u : 0u);
  for (const std::vector<Float4>* layer :
       {&p.channels.inside_diffuse, &p.channels.inside_specular, &p.channels.inside_material})
    if (two_sided) {
      if (layer->size() != p.positions.size())
        throw InputError("cannot save a project whose inside channels and positions differ in size");
      w.texels(*layer);
    }
  w.end_section();

  w.begin_section("LABL");
  w.u32(std::uint32_t(p.labels.size()));
  for (const LabelClass& c : p.labels) {
    w.i32(c.id);
    w.string(c.name);
    w.floats(c.colour.data(), 3);
  }
  w.end_section();

  w.begin_section("HIST");
  w.string(p.history);
  w.end_section();

  w.begin_section("SCAN");
  w.string(p.scan.path);
  w.u64(p.scan.bytes);
  w.u32(p.scan.crc32);
  w.end_section();
}

BaseMesh read_mesh(ByteReader& r)
{
  BaseMesh m;
  r.begin_section("MESH");
  m.name = r.string();
  m.points.resize(r.count(12));
  for (Vec3& v : m.points)
    for (float& x : v)
      x = r.f32();
  m.face_sizes.resize(r.count(4));
  m.face_offsets.assign(1, 0);
  for (int& n : m.face_sizes) {
    n = int(r.u32());
    if (n < 3 || n > (1 << 20))
      r.fail("a face with " + std::to_string(n) + " corners");
    m.face_offsets.push_back(m.face_offsets.back() + n);
  }
  m.face_vertices.resize(r.count(4));
  if (m.face_sizes.empty() || std::size_t(m.face_offsets.back()) != m.face_vertices.size())
    r.fail("face sizes and corner list disagree");
  for (int& v : m.face_vertices) {
    v = int(r.u32());
    if (v < 0 || std::size_t(v) >= m.points.size())
      r.fail("a face corner out of range");
  }
  r.end_section();
  return m;
}

void read_payload(ByteReader& r, Project& p)
{
  p.mesh = read_mesh(r);
  r.begin_section("ATLS");
  p.level = int(r.u32());
  if (p.level < 1 || p.level > kMaxLevel)
    r.fail("level " + std::to_string(p.level) + " is not 1.." + std::to_string(kMaxLevel));
  const std::uint64_t texels = r.u64();
  p.positions = r.texels(std::size_t(texels));
  r.end_section();
  for (const auto& [tag, layer] : {std::pair{"DIFF", &p.channels.diffuse}, std::pair{"SPEC", &p.channels.specular},
                                   std::pair{"MATL", &p.channels.material}}) {
    r.begin_section(tag);
    *layer = r.texels(std::size_t(texels));
    r.end_section();
  }
  r.begin_section("REFP");
  const std::uint64_t reference = r.u64();
  if (reference != 0 && reference != texels)
    r.fail("the reference holds " + std::to_string(reference) + " texels, the atlas " + std::to_string(texels));
  p.reference = r.texels(std::size_t(reference));
  r.end_section();
  r.begin_section("SIDE");
  const std::uint32_t sides = r.u32();
  if (sides > 1)
    r.fail("the side count " + std::to_string(sides) + " is not 0 or 1");
  if (sides == 1)
    for (std::vector<Float4>* layer :
         {&p.channels.inside_diffuse, &p.channels.inside_specular, &p.channels.inside_material})
      *layer = r.texels(std::size_t(texels));
  r.end_section();
  r.begin_section("LABL");
  p.labels.resize(r.count(16));
  for (LabelClass& c : p.labels) {
    c.id = r.i32();
    c.name = r.string();
    for (float& x : c.colour)
      x = r.f32();
  }
  r.end_section();
  r.begin_section("HIST");
  p.history = r.string();
  r.end_section();
  r.begin_section("SCAN");
  p.scan.path = r.string();
  p.scan.bytes = r.u64();
  p.scan.crc32 = r.u32();
  r.end_section();
  if (!r.at_end())
    r.fail("unexpected bytes after the last section");
}

struct FileCloser
{
  void operator()(std::FILE* f) const { std::fclose(f); }
};

} // namespace

bool is_project_path(const std::string& path)
{
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext)
    c = char(std::tolower((unsigned char)c));
  return ext == ".meshpaint";
}

std::uint32_t save_project(const Project& project, const std::string& path)
{
  ByteWriter w;
  write_payload(project, w);
  const std::uint64_t raw_bytes = w.bytes().size();
  std::vector<unsigned char> payload = deflated(w.bytes());
  w.bytes() = {};
  std::vector<unsigned char> header(kHeaderBytes);
  std::copy(std::begin(kMagic), std::end(kMagic), header.begin());
  put_u32(&header[8], kProjectVersion);
  put_u32(&header[12], std::uint32_t(kHeaderBytes));
  put_u64(&header[16], payload.size());
  put_u64(&header[24], raw_bytes);
  put_u32(&header[32], crc_of(payload.data(), payload.size()));
  put_u32(&header[36], crc_of(header.data(), 36));
  write_bytes_atomically(path, {std::string_view(reinterpret_cast<const char*>(header.data()), header.size()),
                               std::string_view(reinterpret_cast<const char*>(payload.data()), payload.size())});
  return get_u32(&header[36]);
}

Project load_project(const std::string& path)
{
  std::unique_ptr<std::FILE, FileCloser> f(std::fopen(path.c_str(), "rb"));
  if (!f)
    throw IOError("cannot read project '" + path + "': " + std::strerror(errno));
  unsigned char header[kHeaderBytes];
  const std::size_t got = std::fread(header, 1, kHeaderBytes, f.get());
  if (got < sizeof(kMagic) || std::memcmp(header, kMagic, sizeof(kMagic)) != 0)
    throw InputError(path + ": not a meshpaint project (no project signature at the start)");
  if (got < 12)
    throw InputError(path + ": truncated project (the header ends early)");
  const std::uint32_t version = get_u32(&header[8]);
  if (version > kProjectVersion)
    throw InputError(path + ": project format version " + std::to_string(version) +
                     " is newer than this meshpaint reads (up to " + std::to_string(kProjectVersion) +
                     "); open it with a newer meshpaint");
  if (got < kHeaderBytes)
    throw InputError(path + ": truncated project (the header ends early)");
  if (version == 0 || get_u32(&header[12]) != kHeaderBytes || get_u32(&header[36]) != crc_of(header, 36))
    throw InputError(path + ": corrupt project (header checksum mismatch)");
  const std::uint64_t packed_bytes = get_u64(&header[16]);
  const std::uint64_t raw_bytes = get_u64(&header[24]);
  std::error_code ec;
  const std::uintmax_t file_bytes = std::filesystem::file_size(path, ec);
  if (ec)
    throw IOError("cannot read project '" + path + "': " + ec.message());
  if (file_bytes < kHeaderBytes + packed_bytes)
    throw InputError(path + ": truncated project (" + std::to_string(file_bytes) + " bytes, the header promises " +
                     std::to_string(kHeaderBytes + packed_bytes) + ")");
  if (file_bytes > kHeaderBytes + packed_bytes)
    throw InputError(path + ": corrupt project (" + std::to_string(file_bytes - kHeaderBytes - packed_bytes) +
                     " bytes after the payload)");
  if (raw_bytes > kMaxRawBytes || raw_bytes > kMaxDeflateRatio * packed_bytes + kDeflateFramingBytes)
    throw InputError(path + ": corrupt project (payload size out of range)");
  std::vector<unsigned char> packed(static_cast<std::size_t>(packed_bytes));
  if (std::fread(packed.data(), 1, packed.size(), f.get()) != packed.size())
    throw IOError("cannot read project '" + path + "'");
  if (crc_of(packed.data(), packed.size()) != get_u32(&header[32]))
    throw InputError(path + ": corrupt project (payload checksum mismatch)");
  const std::vector<unsigned char> raw = inflated(packed, std::size_t(raw_bytes), path);
  packed = {};
  ByteReader r(raw.data(), raw.size(), path);
  Project p;
  read_payload(r, p);
  check_project_content(p, path);
  p.origin = {path, get_u32(&header[36])};
  return p;
}

std::uint32_t project_header_crc(const std::string& path)
{
  std::unique_ptr<std::FILE, FileCloser> f(std::fopen(path.c_str(), "rb"));
  unsigned char header[kHeaderBytes];
  if (!f || std::fread(header, 1, kHeaderBytes, f.get()) != kHeaderBytes ||
      std::memcmp(header, kMagic, sizeof(kMagic)) != 0)
    return 0;
  return get_u32(&header[36]);
}

ScanReference scan_reference(const std::string& path)
{
  std::unique_ptr<std::FILE, FileCloser> f(std::fopen(path.c_str(), "rb"));
  if (!f)
    throw IOError("cannot read '" + path + "': " + std::strerror(errno));
  ScanReference s;
  s.path = path;
  uLong crc = crc32(0L, Z_NULL, 0);
  std::vector<unsigned char> buffer(1 << 20);
  std::size_t n;
  while ((n = std::fread(buffer.data(), 1, buffer.size(), f.get())) > 0) {
    crc = crc32(crc, buffer.data(), uInt(n));
    s.bytes += n;
  }
  if (std::ferror(f.get()))
    throw IOError("cannot read '" + path + "'");
  s.crc32 = std::uint32_t(crc);
  return s;
}

} // namespace meshpaint

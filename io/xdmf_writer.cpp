#include "xdmf_writer.hpp"

#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "atomic_file.hpp"
#include "xml_escape.hpp"

namespace granshock {

namespace {

// Shortest text that reads back as the same double, so the viewer's times match run.h5.
std::string exact(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  return buffer;
}

struct Source {
  std::string dataset;  // path inside the .h5
  const char* number_type;
  int precision;
  bool vector;  // [frames, capacity, dim] (else [frames, capacity])
};

class XdmfBuilder {
 public:
  XdmfBuilder(std::string h5_name, long frame_count, long capacity, int dim)
      : h5_(xml_escape(h5_name)), frames_(frame_count), capacity_(capacity), dim_(dim) {}

  // A HyperSlab DataItem selecting [frame, 0:n, first:first+components] (vector source)
  // or [frame, 0:n] (scalar source), giving an (n, components) or (n) array.
  void hyperslab(std::ostringstream& out, const Source& src, long frame, long n, int first,
                 int components, const char* indent) const {
    const std::string result =
        components > 1 ? std::to_string(n) + " " + std::to_string(components) : std::to_string(n);
    out << indent << "<DataItem ItemType=\"HyperSlab\" Type=\"HyperSlab\" Dimensions=\"" << result
        << "\">\n";
    if (src.vector) {
      out << indent << "  <DataItem Dimensions=\"3 3\" Format=\"XML\" NumberType=\"Int\">" << frame
          << " 0 " << first << "  1 1 1  1 " << n << " " << components << "</DataItem>\n";
    } else {
      out << indent << "  <DataItem Dimensions=\"3 2\" Format=\"XML\" NumberType=\"Int\">" << frame
          << " 0  1 1  1 " << n << "</DataItem>\n";
    }
    out << indent << "  <DataItem Dimensions=\"" << frames_ << " " << capacity_;
    if (src.vector) out << " " << dim_;
    out << "\" NumberType=\"" << src.number_type << "\" Precision=\"" << src.precision
        << "\" Format=\"HDF\">" << h5_ << ":" << src.dataset << "</DataItem>\n";
    out << indent << "</DataItem>\n";
  }

 private:
  std::string h5_;
  long frames_;
  long capacity_;
  int dim_;
};

}  // namespace

void write_particles_xdmf(const std::filesystem::path& xmf_path,
                          const std::string& h5_filename_relative,
                          const std::vector<SnapshotFrame>& frames, int dim, long capacity) {
  if (dim != 2 && dim != 3) throw std::invalid_argument("write_particles_xdmf: dim must be 2 or 3");
  for (const SnapshotFrame& frame : frames) {
    if (frame.count < 0 || frame.count > capacity) {
      throw std::invalid_argument(
          "write_particles_xdmf: frame at step " + std::to_string(frame.step) + " has " +
          std::to_string(frame.count) + " particles, capacity " + std::to_string(capacity));
    }
  }
  const Source position{"/particles/all/position/value", "Float", 8, true};
  const Source velocity{"/particles/all/velocity/value", "Float", 8, true};
  const Source species{"/particles/all/species/value", "Int", 4, false};
  const Source id{"/particles/all/id/value", "Int", 4, false};
  const XdmfBuilder build(h5_filename_relative, static_cast<long>(frames.size()), capacity, dim);

  std::ostringstream out;
  out << "<?xml version=\"1.0\" ?>\n"
      << "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
      << "<Xdmf Version=\"2.0\">\n"
      << "  <Domain>\n"
      << "    <Grid Name=\"particles\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (std::size_t f = 0; f < frames.size(); ++f) {
    const long n = frames[f].count;
    if (n == 0) continue;
    const long frame = static_cast<long>(f);
    out << "      <Grid Name=\"step " << frames[f].step << "\" GridType=\"Uniform\">\n"
        << "        <Time Value=\"" << exact(frames[f].time) << "\"/>\n"
        << "        <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << n
        << "\" NodesPerElement=\"1\"/>\n"
        << "        <Geometry GeometryType=\"" << (dim == 2 ? "XY" : "XYZ") << "\">\n";
    build.hyperslab(out, position, frame, n, 0, dim, "          ");
    out << "        </Geometry>\n";
    auto scalar = [&](const char* name, const Source& src, int component) {
      out << "        <Attribute Name=\"" << name
          << "\" AttributeType=\"Scalar\" Center=\"Node\">\n";
      build.hyperslab(out, src, frame, n, component, 1, "          ");
      out << "        </Attribute>\n";
    };
    scalar("species", species, 0);
    scalar("id", id, 0);
    if (dim == 2) {
      scalar("vx", velocity, 0);
      scalar("vy", velocity, 1);
    } else {
      out << "        <Attribute Name=\"velocity\" AttributeType=\"Vector\" Center=\"Node\">\n";
      build.hyperslab(out, velocity, frame, n, 0, 3, "          ");
      out << "        </Attribute>\n";
    }
    out << "      </Grid>\n";
  }
  out << "    </Grid>\n"
      << "  </Domain>\n"
      << "</Xdmf>\n";
  write_file_atomically(xmf_path, out.str());
}

}  // namespace granshock

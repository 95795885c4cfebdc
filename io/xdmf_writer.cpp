#include "io/xdmf_writer.hpp"

#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "io/atomic_file.hpp"
#include "io/xml_escape.hpp"

namespace granshock {

namespace {

// Shortest text that reads back as the same double, so the viewer's times match run.h5.
std::string exact(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  return buffer;
}

// A DataItem naming the view dataset GROUP/name of n rows (and `components` columns
// when more than one).
std::string data_item(const std::string& h5, const std::string& group, const std::string& name,
                      long n, int components, bool integer) {
  std::ostringstream out;
  out << "<DataItem Dimensions=\"" << n;
  if (components > 1) out << " " << components;
  out << "\" NumberType=\"" << (integer ? "Int" : "Float") << "\" Precision=\"" << (integer ? 4 : 8)
      << "\" Format=\"HDF\">" << h5 << ":" << group << "/" << xml_escape(name) << "</DataItem>";
  return out.str();
}

}  // namespace

void write_particles_xdmf(const std::filesystem::path& xmf_path,
                          const std::string& h5_filename_relative,
                          const std::vector<SnapshotFrame>& frames, int dim,
                          const std::vector<FrameViewArray>& arrays) {
  if (dim != 2 && dim != 3) throw std::invalid_argument("write_particles_xdmf: dim must be 2 or 3");
  for (const SnapshotFrame& frame : frames) {
    if (frame.count < 0) {
      throw std::invalid_argument("write_particles_xdmf: frame at step " +
                                  std::to_string(frame.step) + " has a negative count");
    }
  }
  for (const FrameViewArray& a : arrays) {
    if (a.components != 1 && a.components != 3)
      throw std::invalid_argument("write_particles_xdmf: '" + a.name +
                                  "' is neither a scalar "
                                  "nor a 3-vector");
  }
  const std::string h5 = xml_escape(h5_filename_relative);

  std::ostringstream out;
  out << "<?xml version=\"1.0\" ?>\n"
      << "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
      << "<Xdmf Version=\"2.0\">\n"
      << "  <Domain>\n"
      << "    <Grid Name=\"particles\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (std::size_t f = 0; f < frames.size(); ++f) {
    const long n = frames[f].count;
    if (n == 0) continue;
    const std::string group = frame_view_group(long(f));
    out << "      <Grid Name=\"step " << frames[f].step << "\" GridType=\"Uniform\">\n"
        << "        <Time Value=\"" << exact(frames[f].time) << "\"/>\n"
        << "        <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << n
        << "\" NodesPerElement=\"1\">\n"
        << "          " << data_item(h5, group, "vertex", n, 1, true) << "\n"
        << "        </Topology>\n"
        << "        <Geometry GeometryType=\"" << (dim == 2 ? "XY" : "XYZ") << "\">\n"
        << "          " << data_item(h5, group, "position", n, dim, false) << "\n"
        << "        </Geometry>\n";
    for (const FrameViewArray& a : arrays) {
      out << "        <Attribute Name=\"" << xml_escape(a.name) << "\" AttributeType=\""
          << (a.components == 3 ? "Vector" : "Scalar") << "\" Center=\"Node\">\n"
          << "          " << data_item(h5, group, a.name, n, a.components, a.integer) << "\n"
          << "        </Attribute>\n";
    }
    out << "      </Grid>\n";
  }
  out << "    </Grid>\n"
      << "  </Domain>\n"
      << "</Xdmf>\n";
  write_file_atomically(xmf_path, out.str());
}

}  // namespace granshock

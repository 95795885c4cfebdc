#include "io/fields_xdmf.hpp"

#include <sstream>

#include "io/atomic_file.hpp"
#include "io/xdmf_writer.hpp"
#include "io/xml_escape.hpp"

namespace granshock {

void write_fields_xdmf(const std::filesystem::path& xmf_path, const std::string& h5_name,
                       const FieldsFileContent& c) {
  const std::string h5 = xml_escape(h5_name);
  const std::string cells = std::to_string(c.ny) + " " + std::to_string(c.nx);
  const std::string nodes = std::to_string(c.ny + 1) + " " + std::to_string(c.nx + 1);
  std::ostringstream out;
  out << "<?xml version=\"1.0\" ?>\n"
      << "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
      << "<Xdmf Version=\"2.0\">\n"
      << "  <Domain>\n"
      << "    <Grid Name=\"fields\" GridType=\"Uniform\">\n"
      << "      <Topology TopologyType=\"2DSMesh\" Dimensions=\"" << nodes << "\"/>\n"
      << "      <Geometry GeometryType=\"XY\">\n"
      << "        <DataItem Dimensions=\"" << nodes
      << " 2\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << h5
      << ":/grid/nodes</DataItem>\n"
      << "      </Geometry>\n";
  auto attribute = [&](const std::string& name, const char* type, int precision) {
    out << "      <Attribute Name=\"" << xml_escape(name)
        << "\" AttributeType=\"Scalar\" Center=\"Cell\">\n"
        << "        <DataItem Dimensions=\"" << cells << "\" NumberType=\"" << type
        << "\" Precision=\"" << precision << "\" Format=\"HDF\">" << h5 << ":/fields/"
        << xml_escape(name) << "</DataItem>\n"
        << "      </Attribute>\n";
  };
  for (const auto& f : c.cell_fields) attribute(f.name, "Float", 8);
  for (const auto& f : c.cell_flags) attribute(f.name, "Int", 4);
  for (const CellVector& v : cell_vectors(c)) {
    out << "      <Attribute Name=\"" << xml_escape(v.name)
        << "\" AttributeType=\"Vector\" Center=\"Cell\">\n"
        << "        <DataItem Dimensions=\"" << cells
        << " 3\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << h5 << ":/vectors/"
        << xml_escape(v.name) << "</DataItem>\n"
        << "      </Attribute>\n";
  }
  out << "    </Grid>\n"
      << obstacle_grid_xml(c.obstacle_outline, 2, 4) << "  </Domain>\n"
      << "</Xdmf>\n";
  write_file_atomically(xmf_path, out.str());
}

}  // namespace granshock

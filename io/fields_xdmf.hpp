// fields.xmf: the XDMF 2 description of fields.h5 (fields_file.hpp), so that ParaView or
// VisIt open the averaged fields as one grid of cells with every field a cell attribute.
//
// The grid is a 2DSMesh (structured) with XY geometry read from /grid/nodes, not a
// 2DCoRectMesh: VTK's readers (vtkXdmfReader, vtkXdmf3Reader) map the two dimensions of a
// 2DCoRectMesh to VTK's y and z axes, so the field would lie in the y-z plane, and a
// 3DCoRectMesh needs rank-3 attribute datasets, while fields.h5 stores [ny, nx]. A 2DSMesh
// has explicit x-y node coordinates and [ny, nx] cell data in the same order.
#pragma once

#include <filesystem>
#include <string>

#include "io/fields_file.hpp"

namespace granshock {

// Writes xmf_path atomically; h5_filename_relative is fields.h5 as seen from the XMF's
// directory. Throws UserError when the file cannot be written.
void write_fields_xdmf(const std::filesystem::path& xmf_path,
                       const std::string& h5_filename_relative, const FieldsFileContent& content);

}  // namespace granshock

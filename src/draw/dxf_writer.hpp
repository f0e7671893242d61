// DXF of a drawing through dxflib: AutoCAD 2000 (AC1015), millimetres
// ($INSUNITS 4), a layer per drawing layer with its colour and linetype
// (DASHED defined in the LTYPE table), true LINE, ARC and CIRCLE entities,
// polylines as LWPOLYLINE; entities take colour and linetype BYLAYER.
#pragma once

#include <string>

#include "draw/drawing.hpp"
#include "draw/write_result.hpp"

namespace usina::draw {

WriteResult write_dxf(const Drawing& drawing, std::FILE* file);

// Through core::OutputFile; `inputs` may not be the output.
WriteResult write_dxf_file(const Drawing& drawing, const std::string& path,
                           const std::vector<std::string>& inputs = {});

}  // namespace usina::draw

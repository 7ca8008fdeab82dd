#include "filters/topology/CriticalPoint3D.h"

namespace fluidviz::topology {

std::string toString(CriticalPointType3D t) {
  switch (t) {
    case CriticalPointType3D::Source: return "source";
    case CriticalPointType3D::Sink: return "sink";
    case CriticalPointType3D::Saddle1: return "saddle_1";
    case CriticalPointType3D::Saddle2: return "saddle_2";
    case CriticalPointType3D::SpiralSource: return "spiral_source";
    case CriticalPointType3D::SpiralSink: return "spiral_sink";
    case CriticalPointType3D::SpiralSaddle1: return "spiral_saddle_1";
    case CriticalPointType3D::SpiralSaddle2: return "spiral_saddle_2";
    case CriticalPointType3D::Centre: return "centre";
    case CriticalPointType3D::Degenerate: return "degenerate";
    case CriticalPointType3D::Unknown: return "unknown";
  }
  return "unknown";
}

}  // namespace fluidviz::topology

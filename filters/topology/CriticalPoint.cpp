#include "filters/topology/CriticalPoint.h"

namespace fluidviz::topology {

std::string toString(CriticalPointType t) {
  switch (t) {
    case CriticalPointType::Saddle: return "saddle";
    case CriticalPointType::Source: return "source";
    case CriticalPointType::Sink: return "sink";
    case CriticalPointType::SpiralSource: return "spiral_source";
    case CriticalPointType::SpiralSink: return "spiral_sink";
    case CriticalPointType::Centre: return "centre";
    case CriticalPointType::MonkeySaddle: return "monkey_saddle";
    case CriticalPointType::SaddleNode: return "saddle_node";
    case CriticalPointType::Cusp: return "cusp";
    case CriticalPointType::Dipole: return "dipole";
    case CriticalPointType::Degenerate: return "degenerate";
    case CriticalPointType::Unknown: return "unknown";
    case CriticalPointType::Attachment: return "attachment";
    case CriticalPointType::Separation: return "separation";
  }
  return "unknown";
}

}  // namespace fluidviz::topology

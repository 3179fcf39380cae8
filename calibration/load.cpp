#include "calibration/load.h"

#include "calibration/bourke_mesh.h"
#include "calibration/mpcdi_archive.h"

namespace skyig::calibration {

ProjectorCalibration loadProjector(const ProjectorSource& source) {
  if (!source.bourkeMeshPath.empty()) {
    if (source.bourkeWidth < 2 || source.bourkeHeight < 2)
      throw CalibrationError(source.bourkeMeshPath + ": a warp mesh needs the projector's size");
    return readBourkeMesh(source.bourkeMeshPath, source.bourkeWidth, source.bourkeHeight);
  }
  if (source.mpcdiPath.empty()) throw CalibrationError("a projector names an MPCDI file or a Bourke warp mesh");
  const MpcdiArchive archive(source.mpcdiPath);
  const MpcdiDescription description = parseMpcdiXml(archive.xml(), archive.describe(archive.xmlName()));
  return readMpcdiRegion(archive, description, source.region, source.warpValues);
}

}  // namespace skyig::calibration

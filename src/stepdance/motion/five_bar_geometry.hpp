// The five-bar linkage (digital pantograph, parallel SCARA): its geometry both ways, pure math.
#pragma once

namespace stepdance {

/// Two arms from pivots at (±S/2, 0): the right one (length L1, angle A1) ends at C, the left one
/// (L2, A2) at D; a link of L3 from C and one of L4 from D meet at the elbow E; the tool T sits on
/// an extension of L5 at angle A6 from the L3 link. Angles in radians, lengths in mm; the tool's
/// y is reported mirrored (drawing side positive), as the original library's formula does.
struct FiveBarGeometry {
  double s = 0, l1 = 0, l2 = 0, l3 = 0, l4 = 0, l5 = 0, a6 = 0;

  /// Tool position for arm angles (A1 right, A2 left). False (outputs untouched) when the links
  /// cannot close at those angles.
  bool forward(double a1, double a2, double& x, double& y) const;
  /// Arm angles that put the tool at (x, y), in the configuration forward() computes (checked by
  /// running forward on the answer). False when the point is out of reach.
  bool inverse(double x, double y, double& a1, double& a2) const;
};

}  // namespace stepdance

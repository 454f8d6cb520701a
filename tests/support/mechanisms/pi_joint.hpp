// Active Π-joint test fixtures ([Milutinovic]): the bundled prototype.
#pragma once

#include "pkmws/io/mechanism_file.hpp"
#include "mechanisms/pi_joint/pi_joint.hpp"
#include "support/fixtures.hpp"

namespace pkmws::test::pi_joint {

/// datasets/pi_joint_prototype.json, loaded once.
inline const mechanisms::PiJoint& prototype() {
  static const io::MechanismFile f = io::load_mechanism(dataset("pi_joint_prototype"));
  return dynamic_cast<const mechanisms::PiJoint&>(*f.model);
}

}  // namespace pkmws::test::pi_joint

#pragma once
#include <string>

namespace uabt::testing {

// msl_curiosity's trees, written out by hand the way a compiled tree may look. Tests build a
// compiled document from them and replace one part.
inline std::string msl_main_tree(
    const std::string& navigation_call = "<SubTree ID=\"navigation\" _autoremap=\"true\"/>") {
  return "  <BehaviorTree ID=\"MainTree\">\n"
         "    <Sequence name=\"root_sequence\">\n"
         "      <Fallback name=\"reach_target\">\n"
         "        <IsInLocation/>\n"
         "        " +
         navigation_call +
         "\n"
         "      </Fallback>\n"
         "      <Stop/>\n"
         "      <Sequence name=\"collect_sample\">\n"
         "        <Fallback>\n"
         "          <IsArmInPosition function=\"drilling\"/>\n"
         "          <OpenToolArm/>\n"
         "        </Fallback>\n"
         "        <Fallback>\n"
         "          <IsDug/>\n"
         "          <Drill/>\n"
         "        </Fallback>\n"
         "        <Fallback>\n"
         "          <IsContainerEmpty/>\n"
         "          <Trickle/>\n"
         "        </Fallback>\n"
         "        <Fallback>\n"
         "          <IsPictureTaken/>\n"
         "          <TakePicture/>\n"
         "        </Fallback>\n"
         "        <Fallback>\n"
         "          <IsArmInPosition function=\"closing_arm\"/>\n"
         "          <CloseToolArm/>\n"
         "        </Fallback>\n"
         "      </Sequence>\n"
         "    </Sequence>\n"
         "  </BehaviorTree>\n";
}

inline std::string msl_alternative_trees(const std::string& dust_speed = "2.0") {
  return "  <BehaviorTree ID=\"on_dust\">\n"
         "    <Sequence>\n"
         "      <Fallback>\n"
         "        <IsTowardObject/>\n"
         "        <TurnRight angle=\"180\"/>\n"
         "      </Fallback>\n"
         "      <MoveForward name=\"drive\" time=\"2\" speed=\"" +
         dust_speed +
         "\"/>\n"
         "    </Sequence>\n"
         "  </BehaviorTree>\n"
         "  <BehaviorTree ID=\"on_rocks\">\n"
         "    <Sequence>\n"
         "      <Fallback>\n"
         "        <Inverter>\n"
         "          <IsTowardObject/>\n"
         "        </Inverter>\n"
         "        <Fallback>\n"
         "          <IsRockAtLeft/>\n"
         "          <TurnRight angle=\"180\"/>\n"
         "        </Fallback>\n"
         "        <Fallback>\n"
         "          <IsRockAtRight/>\n"
         "          <TurnLeft angle=\"180\"/>\n"
         "        </Fallback>\n"
         "      </Fallback>\n"
         "      <MoveBackward name=\"drive\" time=\"10\" speed=\"0.4\"/>\n"
         "    </Sequence>\n"
         "  </BehaviorTree>\n"
         "  <BehaviorTree ID=\"hold_position\">\n"
         "    <Sequence>\n"
         "      <Stop/>\n"
         "      <WaitForGroundCommand/>\n"
         "    </Sequence>\n"
         "  </BehaviorTree>\n";
}

inline const char* const kDustBranch =
    "<Sequence name=\"Req1\"><OnDust/><SubTree ID=\"on_dust\" _autoremap=\"true\"/></Sequence>";
inline const char* const kRocksBranch =
    "<Sequence name=\"Req2\"><OnRocks/><SubTree ID=\"on_rocks\" _autoremap=\"true\"/></Sequence>";
inline const char* const kSafeBranch =
    "<Sequence name=\"Safe\"><SubTree ID=\"hold_position\" _autoremap=\"true\"/></Sequence>";

inline std::string msl_selector(const std::string& branches,
                                const std::string& root = "Fallback name=\"navigation\"") {
  const std::string close = root.substr(0, root.find(' '));
  return "  <BehaviorTree ID=\"navigation\">\n    <" + root + ">\n      " + branches + "\n    </" +
         close + ">\n  </BehaviorTree>\n";
}

inline std::string msl_document(const std::string& selector,
                                const std::string& main = msl_main_tree(),
                                const std::string& alternatives = msl_alternative_trees(),
                                const std::string& extra = "") {
  return "<root BTCPP_format=\"4\" main_tree_to_execute=\"MainTree\">\n" + main + selector +
         alternatives + extra + "</root>\n";
}

inline std::string msl_default_selector() {
  return msl_selector(std::string(kDustBranch) + "\n      " + kRocksBranch + "\n      " +
                      kSafeBranch);
}

}  // namespace uabt::testing

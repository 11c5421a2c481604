#include "devices/canopen/nmt_slave.h"

#include "devices/canopen/node.h"

namespace canopen {

void NmtSlave::on_frame(const sim::CanFrame& frame) {
  if (frame.rtr) return;
  const bool dlc_ok = node_.policy().nmt.require_dlc_2 ? frame.dlc == 2 : frame.dlc >= 2;
  if (!dlc_ok) return;
  const std::uint8_t target = frame.data[1];
  if (target != 0 && target != node_.node_id()) return;
  switch (frame.data[0]) {
    case 0x01: node_.execute_nmt(NmtCommand::Start); break;
    case 0x02:
      if (node_.policy().nmt.stop_supported) node_.execute_nmt(NmtCommand::Stop);
      break;
    case 0x80: node_.execute_nmt(NmtCommand::EnterPreOperational); break;
    case 0x81: node_.execute_nmt(NmtCommand::ResetNode); break;
    case 0x82: node_.execute_nmt(NmtCommand::ResetCommunication); break;
    default: break;  // unknown command specifiers are ignored
  }
}

}  // namespace canopen

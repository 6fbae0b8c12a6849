# placeholder until ParaView is configured

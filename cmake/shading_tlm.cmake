# shading_tlm: the TLM-2.0 wrappers (modules/tlm, header-only) of the UA 60553 device family,
# every variant (the ROM one needs shading_ua22802's generated content). The wrappers need the floor
# alone (their loosely-timed mode calls its device functions, through shading_modules); shading_golden
# comes along for the platform's own checks against the golden models (docs/platform.md: shading::tlm
# gives the modules and the golden models).
add_library(shading_tlm INTERFACE)
target_link_libraries(shading_tlm INTERFACE shading_modules shading_golden shading_ua22802)

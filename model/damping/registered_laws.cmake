# The registered damping laws, in the order every list of laws shows them (`hertzdash models`,
# the --damping choices, the figures, the standard tests). One line per law: its class, then its
# header in model/damping/laws/. Adding a law is its header there plus its line here
# (model/README.md).
#
# CMake reads this list (model/CMakeLists.txt) and generates from it the header that includes the
# laws as types (RegisteredLaws, model/damping/registered_law_types.hpp) and one translation unit
# per law that compiles everything that runs the law (simulation/run/law_instantiation.cpp.in), so
# editing one law's header recompiles that law's code only.
set(HERTZDASH_REGISTERED_LAWS
  Undamped             undamped.hpp
  HongoPaper           hongo_paper.hpp
  KelvinVoigt          kelvin_voigt.hpp
  HuntCrossley         hunt_crossley.hpp
  HerbertMcWhannell    herbert_mcwhannell.hpp
  LeeWang              lee_wang.hpp
  LankaraniNikravesh   lankarani_nikravesh.hpp
  Gonthier             gonthier.hpp
  ZhiyingQishao        zhiying_qishao.hpp
  Flores               flores.hpp
  HuGuo                hu_guo.hpp
  GharibHurmuzlu       gharib_hurmuzlu.hpp
  TsujiDem             tsuji_dem.hpp
  KuwabaraKono         kuwabara_kono.hpp
  LeeHerrmann          lee_herrmann.hpp
)

#pragma once
// The NREL 5MW aeroelastic Campbell point at 9 rpm, 8 m/s, as OpenFAST gives it: MBC3 [Bir2010] of
// OpenFAST v3.3's tests/data/openfast-lin/rotating-9rpm/Main.{1,12,24}.lin averaged over the 3
// azimuths, as OpenFAST's python toolbox stores it for these files (shared/ref/
// openfast_rotating_9rpm_mbc.csv), printed with 4 decimals. Two tests use it: whirl's MBC of OpenFAST's
// own .lin files (to the printed digits) and whirl's own linearization of the same deck (to the
// issue's acceptance).

namespace whirl::test {

struct OpenFast9rpmMode {
  const char* mode;
  double freq_hz, damping_ratio;
};

/// The modes above 0.1 Hz, sorted by frequency.
inline constexpr OpenFast9rpmMode kOpenFast9rpmMbc3[] = {{"1st flap BW", 0.5878, 0.6311},
                                                         {"1st flap collective", 0.7225, 0.5253},
                                                         {"1st flap FW", 0.8416, 0.4401},
                                                         {"1st edge BW", 0.9371, 0.0163},
                                                         {"1st edge FW", 1.2371, 0.0124},
                                                         {"2nd flap BW", 1.8373, 0.1555},
                                                         {"2nd flap collective", 1.9870, 0.1429},
                                                         {"2nd flap FW", 2.1337, 0.1338},
                                                         {"1st edge collective (with generator)", 2.2561, 0.0226}};

}  // namespace whirl::test

#include "src/io/openfast/openfast_layouts.hpp"

namespace whirl::io {

// Keys in the order OpenFAST reads them, versions merged (a key a version dropped stays at its place);
// `Name(k)` is an array (`Name(1)`, `Name1`, …). Sources: the reader routines named in the header, at
// the tags v2.6.0 … v5.0.0, and docs/source/user/api_change.rst (OpenFAST/openfast).

const OpenFastLayout& aeroDynLayout() {
  static const OpenFastLayout l{"AeroDyn v15",
                                {"Echo",
                                 "DTAero",
                                 "WakeMod",
                                 "Wake_Mod",
                                 "AFAeroMod",
                                 "TwrPotent",
                                 "TwrShadow",
                                 "TwrAero",
                                 "FrozenWake",
                                 "CavitCheck",
                                 "NacelleDrag",
                                 "Buoyancy",
                                 "CompAA",
                                 "AA_InputFile",
                                 "MHK",
                                 "AirDens",
                                 "KinVisc",
                                 "SpdSound",
                                 "Patm",
                                 "Pvap",
                                 "FluidDepth",
                                 "BEM_Mod",
                                 "SkewMod",
                                 "Skew_Mod",
                                 "SkewMomCorr",
                                 "SkewRedistr_Mod",
                                 "SkewModFactor",
                                 "SkewRedistrFactor",
                                 "TipLoss",
                                 "HubLoss",
                                 "TanInd",
                                 "AIDrag",
                                 "TIDrag",
                                 "IndToler",
                                 "MaxIter",
                                 "SectAvg",
                                 "SectAvgWeighting",
                                 "SectAvgNPoints",
                                 "SectAvgPsiBwd",
                                 "SectAvgPsiFwd",
                                 "DBEMT_Mod",
                                 "tau1_const",
                                 "OLAFInputFileName",
                                 "AoA34",
                                 "UAMod",
                                 "UA_Mod",
                                 "FLookup",
                                 "IntegrationMethod",
                                 "UAStartRad",
                                 "UAEndRad",
                                 "AFTabMod",
                                 "InCol_Alfa",
                                 "InCol_Cl",
                                 "InCol_Cd",
                                 "InCol_Cm",
                                 "InCol_Cpmin",
                                 "NumAFfiles",
                                 "AFNames",
                                 "UseBlCm",
                                 "ADBlFile(k)",
                                 "VolHub",
                                 "HubCenBx",
                                 "VolNac",
                                 "NacCenB",
                                 "NacArea",
                                 "NacCd",
                                 "NacDragAC",
                                 "TFinAero",
                                 "TFinFile",
                                 "NumTwrNds",
                                 "SumPrint",
                                 "NBlOuts",
                                 "BlOutNd",
                                 "NTwOuts",
                                 "TwOutNd",
                                 "BldNd_BladesOut",
                                 "BldNd_BlOutNd"},
                                // OpenFAST v5 repeats the hub, nacelle, tail-fin and tower sections once per rotor
                                // (AeroDyn_IO.f90, ParsePrimaryFileInfo: "do iR = 1,size(NumBlades)").
                                {"VolHub", "HubCenBx", "VolNac", "NacCenB", "NacArea", "NacCd", "NacDragAC", "TFinAero",
                                 "TFinFile", "NumTwrNds"}};
  return l;
}

const OpenFastLayout& aeroDynBladeLayout() {
  static const OpenFastLayout l{"AeroDyn blade", {"NumBlNds"}, {}};
  return l;
}

const OpenFastLayout& airfoilLayout() {
  // The keys from Re to NumAlf belong to one table and repeat per table (NumTabs); a table's own
  // keys are checked once more table by table (readAirfoil), where none may repeat.
  static const OpenFastLayout l{"AeroDyn airfoil",
                                {"InterpOrd",  "RelThickness", "NonDimArea", "NumCoords",  "BL_file",
                                 "NumTabs",    "Re",           "UserProp",   "Ctrl",       "InclUAdata",
                                 "alpha0",     "alpha1",       "alpha2",     "alphaUpper", "alphaLower",
                                 "eta_e",      "C_nalpha",     "C_lalpha",   "T_f0",       "T_V0",
                                 "T_p",        "T_VL",         "b1",         "b2",         "b5",
                                 "A1",         "A2",           "A5",         "S1",         "S2",
                                 "S3",         "S4",           "Cn1",        "Cn2",        "St_sh",
                                 "Cd0",        "Cm0",          "k0",         "k1",         "k2",
                                 "k3",         "k1_hat",       "x_cp_bar",   "UACutout",   "UACutout_delta",
                                 "filtCutOff", "NumAlf"},
                                {"Re",         "UserProp",   "Ctrl",
                                 "InclUAdata", "alpha0",     "alpha1",
                                 "alpha2",     "alphaUpper", "alphaLower",
                                 "eta_e",      "C_nalpha",   "C_lalpha",
                                 "T_f0",       "T_V0",       "T_p",
                                 "T_VL",       "b1",         "b2",
                                 "b5",         "A1",         "A2",
                                 "A5",         "S1",         "S2",
                                 "S3",         "S4",         "Cn1",
                                 "Cn2",        "St_sh",      "Cd0",
                                 "Cm0",        "k0",         "k1",
                                 "k2",         "k3",         "k1_hat",
                                 "x_cp_bar",   "UACutout",   "UACutout_delta",
                                 "filtCutOff", "NumAlf"}};
  return l;
}

const OpenFastLayout& inflowWindLayout() {
  static const OpenFastLayout l{"InflowWind",
                                {"Echo",
                                 "WindType",
                                 "PropagationDir",
                                 "VFlowAng",
                                 "VelInterpCubic",
                                 "NWindVel",
                                 "WindVxiList",
                                 "WindVyiList",
                                 "WindVziList",
                                 "HWindSpeed",
                                 "RefHt",
                                 "PLexp",
                                 "FileName_Uni",
                                 "Filename",
                                 "RefHt_Uni",
                                 "RefLength",
                                 "FileName_BTS",
                                 "FilenameRoot",
                                 "TowerFile",
                                 "FileName_u",
                                 "FileName_v",
                                 "FileName_w",
                                 "nx",
                                 "ny",
                                 "nz",
                                 "dx",
                                 "dy",
                                 "dz",
                                 "RefHt_HAWC",
                                 "ScaleMethod",
                                 "SFx",
                                 "SFy",
                                 "SFz",
                                 "SigmaFx",
                                 "SigmaFy",
                                 "SigmaFz",
                                 "URef",
                                 "WindProfile",
                                 "PLExp_HAWC",
                                 "Z0",
                                 "XOffset",
                                 "SensorType",
                                 "NumPulseGate",
                                 "PulseSpacing",
                                 "NumBeam",
                                 "FocalDistanceX",
                                 "FocalDistanceY",
                                 "FocalDistanceZ",
                                 "RotorApexOffsetPos",
                                 "URefLid",
                                 "MeasurementInterval",
                                 "LidRadialVel",
                                 "ConsiderHubMotion",
                                 "SumPrint"},
                                // FAST v8's InflowWind v3.01 labels the uniform and the Bladed-style files both
                                // `Filename`, and repeats `RefHt` (uniform, full-field) and `PLExp` (HAWC) in later
                                // sections than the steady wind's (the first, the one whirl reads).
                                {"Filename", "RefHt", "PLExp"},
                                false};
  return l;
}

const OpenFastLayout& hydroDynLayout() {
  static const OpenFastLayout l{"HydroDyn",
                                {"Echo",         "WtrDens",         "WtrDpth",         "MSL2SWL",
                                 "WaveMod",      "WaveStMod",       "WaveTMax",        "WaveDT",
                                 "WaveHs",       "WaveTp",          "WavePkShp",       "WvLowCOff",
                                 "WvHiCOff",     "WaveDir",         "WaveDirMod",      "WaveDirSpread",
                                 "WaveNDir",     "WaveDirRange",    "WaveSeed(k)",     "WaveNDAmp",
                                 "WvKinFile",    "NWaveElev",       "WaveElevxi",      "WaveElevyi",
                                 "WvDiffQTF",    "WvSumQTF",        "WvLowCOffD",      "WvHiCOffD",
                                 "WvLowCOffS",   "WvHiCOffS",       "CurrMod",         "CurrSSV0",
                                 "CurrSSDir",    "CurrNSRef",       "CurrNSV0",        "CurrNSDir",
                                 "CurrDIV",      "CurrDIDir",       "PotMod",          "ExctnMod",
                                 "ExctnDisp",    "ExctnCutOff",     "PtfmYMod",        "PtfmRefY",
                                 "PtfmYCutOff",  "NExctnHdg",       "RdtnMod",         "RdtnTMax",
                                 "RdtnDT",       "NBody",           "NBodyMod",        "PotFile",
                                 "PotFile(k)",   "WAMITULEN",       "PtfmRefxt",       "PtfmRefyt",
                                 "PtfmRefzt",    "PtfmRefztRot",    "PtfmVol0",        "PtfmCOBxt",
                                 "PtfmCOByt",    "NAddDOF",         "MnDrift",         "NewmanApp",
                                 "DiffQTF",      "SumQTF",          "PtfmSgF",         "PtfmSwF",
                                 "PtfmHvF",      "PtfmRF",          "PtfmPF",          "PtfmYF",
                                 "AddF0",        "AddCLin",         "AddBLin",         "AddBQuad",
                                 "WaveDisp",     "AMMod",           "HstMod",          "NAxCoef",
                                 "NAxCoefs",     "NJoints",         "NPropSets",       "NPropSetsCyl",
                                 "NPropSetsRec", "NCoefDpth",       "NCoefDpthCyl",    "NCoefDpthRec",
                                 "NCoefMembers", "NCoefMembersCyl", "NCoefMembersRec", "NMembers",
                                 "NFillGroups",  "NMGDepths",       "NMOutputs",       "NJOutputs",
                                 "JOutLst",      "HDSum",           "OutAll",          "OutSwtch",
                                 "OutFmt",       "OutSFmt"},
                                {}};
  return l;
}

const OpenFastLayout& seaStateLayout() {
  static const OpenFastLayout l{
      "SeaState",
      {"Echo",         "WtrDens",     "WtrDpth",    "MSL2SWL",    "X_HalfWidth",   "Y_HalfWidth",
       "Z_Depth",      "NX",          "NY",         "NZ",         "WaveMod",       "WaveStMod",
       "WvCrntMod",    "WaveTMax",    "WaveDT",     "WaveHs",     "WaveTp",        "WavePkShp",
       "WvLowCOff",    "WvHiCOff",    "WaveDir",    "WaveDirMod", "WaveDirSpread", "WaveNDir",
       "WaveDirRange", "WaveSeed(k)", "WaveNDAmp",  "WvKinFile",  "WvDiffQTF",     "WvSumQTF",
       "WvLowCOffD",   "WvHiCOffD",   "WvLowCOffS", "WvHiCOffS",  "ConstWaveMod",  "CrestHmax",
       "CrestTime",    "CrestXi",     "CrestYi",    "CurrMod",    "CurrSSV0",      "CurrSSDir",
       "CurrNSRef",    "CurrNSV0",    "CurrNSDir",  "CurrDIV",    "CurrDIDir",     "MCFD",
       "SeaStSum",     "OutSwtch",    "OutFmt",     "OutSFmt",    "NWaveElev",     "WaveElevxi",
       "WaveElevyi",   "NWaveKin",    "WaveKinxi",  "WaveKinyi",  "WaveKinzi"},
      {}};
  return l;
}

const OpenFastLayout& servoDynLayout() {
  static const OpenFastLayout l{
      "ServoDyn",
      {"Echo",         "DT",           "PCMode",       "TPCOn",      "TPitManS(k)",  "PitManRat(k)", "BlPitchF(k)",
       "PitNeut(k)",   "PitSpr(k)",    "PitDamp(k)",   "VSContrl",   "GenModel",     "GenEff",       "GenTiStr",
       "GenTiStp",     "SpdGenOn",     "TimGenOn",     "TimGenOf",   "VS_RtGnSp",    "VS_RtTq",      "VS_Rgn2K",
       "VS_SlPc",      "SIG_SlPc",     "SIG_SySp",     "SIG_RtTq",   "SIG_PORt",     "TEC_Freq",     "TEC_NPol",
       "TEC_SRes",     "TEC_RRes",     "TEC_VLL",      "TEC_SLR",    "TEC_RLR",      "TEC_MR",       "HSSBrMode",
       "THSSBrDp",     "HSSBrDT",      "HSSBrTqF",     "YCMode",     "TYCOn",        "YawNeut",      "YawSpr",
       "YawDamp",      "TYawManS",     "YawManRat",    "NacYawF",    "AfCmode",      "AfC_Mean",     "AfC_Amp",
       "AfC_Phase",    "CCmode",       "CompNTMD",     "NTMDfile",   "CompTTMD",     "TTMDfile",     "NumBStC",
       "BStCfiles",    "NumNStC",      "NStCfiles",    "NumTStC",    "TStCfiles",    "NumSStC",      "SStCfiles",
       "DLL_FileName", "DLL_InFile",   "DLL_ProcName", "DLL_DT",     "DLL_Ramp",     "BPCutoff",     "NacYaw_North",
       "Ptch_Cntrl",   "Ptch_SetPnt",  "Ptch_Min",     "Ptch_Max",   "PtchRate_Min", "PtchRate_Max", "Gain_OM",
       "GenSpd_MinOM", "GenSpd_MaxOM", "GenSpd_Dem",   "GenTrq_Dem", "GenPwr_Dem",   "DLL_NumTrq",   "SumPrint",
       "OutFile",      "TabDelim",     "OutFmt",       "TStart"},
      {},
      false};
  return l;
}

const OpenFastLayout& fstLayout() {
  static const OpenFastLayout l{
      ".fst",
      {"Echo",         "AbortLevel", "TMax",        "DT",          "ModCoupling", "InterpOrder", "NumCrctn",
       "RhoInf",       "ConvTol",    "MaxConvIter", "DT_UJac",     "UJacSclFact", "NRotors",     "CompElast",
       "CompInflow",   "CompAero",   "CompServo",   "CompSeaSt",   "CompHydro",   "CompSub",     "CompMooring",
       "CompIce",      "CompSoil",   "MHK",         "MirrorRotor", "Gravity",     "AirDens",     "WtrDens",
       "KinVisc",      "SpdSound",   "Patm",        "Pvap",        "WtrDpth",     "MSL2SWL",     "EDFile",
       "BDBldFile(k)", "InflowFile", "AeroFile",    "ADFile",      "ServoFile",   "SrvDFile",    "SeaStFile",
       "HydroFile",    "SubFile",    "MooringFile", "IceFile",     "SoilFile",    "SumPrint",    "SttsTime",
       "ChkptTime",    "DT_Out",     "TStart",      "OutFileFmt",  "TabDelim",    "OutFmt",      "Linearize",
       "CalcSteady",   "TrimCase",   "TrimTol",     "TrimGain",    "Twr_Kdmp",    "Bld_Kdmp",    "NLinTimes",
       "LinTimes",     "LinInputs",  "LinOutputs",  "LinOutJac",   "LinOutMod",   "WrVTK",       "VTK_type",
       "VTK_fields",   "VTK_fps"},
      // OpenFAST v5 repeats the per-rotor lines for each rotor after the first (FAST_Subs.f90,
      // FAST_ReadPrimaryFile: "EDFile … for rotor iRot").
      {"EDFile", "BDBldFile(k)", "ServoFile", "SrvDFile"},
      false};
  return l;
}

}  // namespace whirl::io

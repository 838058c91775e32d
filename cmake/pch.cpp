// The translation unit that builds the precompiled headers every stage and test reuses
// (CMakeLists.txt, UABT_PCH).

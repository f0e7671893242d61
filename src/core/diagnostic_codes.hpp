// Every diagnostic usina reports, with its stable name (docs/errors.md).
// X(Enumerator, STABLE_NAME). Append only: the names are a contract.
#pragma once

#define USINA_DIAGNOSTIC_CODES(X)                                \
  /* input and limits */                                         \
  X(FileNotFound, E_FILE_NOT_FOUND)                              \
  X(FileTooLarge, E_FILE_TOO_LARGE)                              \
  X(NoProgramEnd, W_NO_PROGRAM_END)                              \
  X(ByteOrderMark, W_BYTE_ORDER_MARK)                            \
  X(TextAfterProgramEnd, W_TEXT_AFTER_END)                       \
  /* lexer and parser */                                         \
  X(UnexpectedCharacter, E_UNEXPECTED_CHARACTER)                 \
  X(BadNumber, E_BAD_NUMBER)                                     \
  X(UnclosedComment, E_UNCLOSED_COMMENT)                         \
  X(UnclosedBracket, E_UNCLOSED_BRACKET)                         \
  X(ExpectedExpression, E_EXPECTED_EXPRESSION)                   \
  X(UnknownFunction, E_UNKNOWN_FUNCTION)                         \
  X(BadParameterName, E_BAD_PARAMETER_NAME)                      \
  X(BadOWord, E_BAD_O_WORD)                                      \
  X(MisplacedOWord, E_MISPLACED_O_WORD)                          \
  X(UnknownWord, E_UNKNOWN_WORD)                                 \
  /* expressions and parameters */                               \
  X(DivisionByZero, E_DIVISION_BY_ZERO)                          \
  X(DomainError, E_DOMAIN_ERROR)                                 \
  X(ParameterOutOfRange, E_PARAMETER_OUT_OF_RANGE)               \
  X(ReadOnlyParameter, E_READ_ONLY_PARAMETER)                    \
  X(UndefinedParameter, E_UNDEFINED_PARAMETER)                   \
  X(NumberOutOfRange, E_NUMBER_OUT_OF_RANGE)                     \
  X(BadVarFile, E_BAD_VAR_FILE)                                  \
  /* control flow */                                             \
  X(UnknownSubroutine, E_UNKNOWN_SUBROUTINE)                     \
  X(UnclosedBlock, E_UNCLOSED_CONTROL_BLOCK)                     \
  X(UnmatchedControl, E_UNMATCHED_CONTROL)                       \
  X(RecursionTooDeep, E_RECURSION_TOO_DEEP)                      \
  X(TooManyIterations, E_TOO_MANY_ITERATIONS)                    \
  X(BadSubroutineName, E_BAD_SUBROUTINE_NAME)                    \
  X(DuplicateSubroutine, E_DUPLICATE_SUBROUTINE)                 \
  /* block checks */                                             \
  X(ModalGroupConflict, E_MODAL_GROUP_CONFLICT)                  \
  X(RepeatedWord, E_REPEATED_WORD)                               \
  X(UnknownGCode, E_UNKNOWN_G_CODE)                              \
  X(UnknownMCode, E_UNKNOWN_M_CODE)                              \
  X(UnusedWord, E_UNUSED_WORD)                                   \
  X(MissingWord, E_MISSING_WORD)                                 \
  X(BadWordValue, E_BAD_WORD_VALUE)                              \
  X(AxisWordsConflict, E_AXIS_WORDS_CONFLICT)                    \
  X(NoFeedRate, E_NO_FEED_RATE)                                  \
  X(NotAllowedInMode, E_NOT_ALLOWED_IN_MODE)                     \
  /* arcs */                                                     \
  X(ArcRadiusMismatch, E_ARC_RADIUS_MISMATCH)                    \
  X(ArcRadiusTooSmall, E_ARC_RADIUS_TOO_SMALL)                   \
  X(ArcMissingCenter, E_ARC_MISSING_CENTER)                      \
  X(ArcZeroLength, E_ARC_ZERO_LENGTH)                            \
  /* cutter compensation and tools */                            \
  X(CutterGouge, E_CUTTER_GOUGE)                                 \
  X(CompEntryMove, E_COMP_ENTRY_MOVE)                            \
  X(CompToolTooBig, E_COMP_TOOL_TOO_BIG)                         \
  X(CompNotAllowed, E_COMP_NOT_ALLOWED)                          \
  X(UnknownTool, E_UNKNOWN_TOOL)                                 \
  X(BadToolTable, E_BAD_TOOL_TABLE)                              \
  /* canned cycles and probing */                                \
  X(CycleBadValue, E_CYCLE_BAD_VALUE)                            \
  X(ProbeBadMove, E_PROBE_BAD_MOVE)                              \
  X(SplineBadValue, E_SPLINE_BAD_VALUE)                          \
  /* operator messages */                                        \
  X(Message, N_MESSAGE)                                          \
  X(Unsupported, E_UNSUPPORTED)                                  \
  /* machine profiles (sim) */                                   \
  X(BadMachineProfile, E_BAD_MACHINE_PROFILE)                    \
  /* program checks (usina stats) */                             \
  X(OverTravel, W_OVERTRAVEL)                                    \
  X(FeedWithoutRate, W_FEED_WITHOUT_RATE)                        \
  X(FeedSpindleStopped, W_FEED_SPINDLE_STOPPED)                  \
  X(RapidIntoStock, W_RAPID_INTO_STOCK)                          \
  X(ArcFeedReduced, W_ARC_FEED_REDUCED)                          \
  X(FeedClamped, W_FEED_CLAMPED)                                 \
  /* the romi dialect */                                         \
  X(TypographicDash, W_TYPOGRAPHIC_DASH)                         \
  X(PolarWithXy, E_POLAR_WITH_XY)                                \
  X(NoTangentDirection, E_NO_TANGENT_DIRECTION)                  \
  X(BlendNeedsMove, E_BLEND_NEEDS_MOVE)                          \
  X(ScaleOutOfRange, E_SCALE_OUT_OF_RANGE)                       \
  X(UnequalScaleArc, E_UNEQUAL_SCALE_ARC)                        \
  X(UnknownToolDiameter, E_UNKNOWN_TOOL_DIAMETER)                \
  X(PocketTooSmall, E_POCKET_TOO_SMALL)                          \
  X(UnknownBlockNumber, E_UNKNOWN_BLOCK_NUMBER)                  \
  X(DepthSignIgnored, N_DEPTH_SIGN_IGNORED)                      \
  /* cam generators: drawings, fonts, values */                  \
  X(DxfUnreadable, E_DXF_UNREADABLE)                             \
  X(DxfNoEntities, E_DXF_NO_ENTITIES)                            \
  X(DxfUnsupportedEntity, W_DXF_UNSUPPORTED)                     \
  X(GenBadValue, E_GEN_BAD_VALUE)                                \
  X(GenToolTooBig, E_GEN_TOOL_TOO_BIG)                           \
  X(GenOpenOutline, E_GEN_OPEN_OUTLINE)                          \
  X(FontUnreadable, E_FONT_UNREADABLE)                           \
  X(TextNotInFont, E_TEXT_NOT_IN_FONT)                           \
  /* the grbl dialect */                                         \
  X(GrblError, E_GRBL)                                           \
  X(GrblWarning, W_GRBL)                                         \
  /* the fanuc dialect */                                        \
  X(IntegerCoordinate, W_INTEGER_COORDINATE)                     \
  X(MacroAlarm, E_MACRO_ALARM)                                   \
  X(MacroFormat, E_MACRO_FORMAT)                                 \
  X(BadLoop, E_BAD_LOOP)                                         \
  X(DialectGuess, N_DIALECT_GUESS)                               \
  X(GrblAlarm, E_GRBL_ALARM)                                     \
  X(ForbiddenArea, E_FORBIDDEN_AREA)                             \
  X(ParameterNotModeled, W_PARAMETER_NOT_MODELED)                \
  X(IncrementalAfterG69, W_INCREMENTAL_AFTER_G69)                \
  X(PolarThroughCentre, E_POLAR_THROUGH_CENTRE)                  \
  /* gen: limits, material left, option names */                 \
  X(GenTooMuchWork, E_GEN_TOO_MUCH_WORK)                         \
  X(GenMaterialLeft, E_GEN_MATERIAL_LEFT)                        \
  X(GenNoEffect, W_GEN_NO_EFFECT)                                \
  X(DeprecatedOption, W_DEPRECATED_OPTION)                       \
  X(UnknownProfileKey, W_UNKNOWN_PROFILE_KEY)                    \
  /* limits: blocks, operations */                               \
  X(BlockTooLong, E_BLOCK_TOO_LONG)                              \
  X(TooManyOperations, E_TOO_MANY_OPERATIONS)                    \
  /* limits: numbers */                                          \
  X(ValueOutOfRange, E_VALUE_OUT_OF_RANGE)                       \
  X(UnknownRegister, W_UNKNOWN_OFFSET_REGISTER)                  \
  X(VarFileLineSkipped, W_VAR_FILE_LINE_SKIPPED)                 \
  X(VarFileExtraText, W_VAR_FILE_EXTRA_TEXT)                     \
  X(ToolWithoutPocket, W_TOOL_WITHOUT_POCKET)                    \
  X(ToolRedefined, W_TOOL_REDEFINED)                             \
  /* dxf: the reader's checks of a drawing's lines and groups */ \
  X(DxfMalformed, E_DXF_MALFORMED)                               \
  /* dnc: links, tape codes, transfers */                        \
  X(DncConfig, E_DNC_CONFIG)                                     \
  X(UnknownDncKey, W_UNKNOWN_DNC_KEY)                            \
  X(TapeNoCode, E_TAPE_NO_CODE)                                  \
  X(TapeParity, E_TAPE_PARITY)                                   \
  X(RemoteRequest, E_REMOTE_REQUEST)                             \
  /* rs274ngc: '%' lines (issue 12, real programs) */            \
  X(MisplacedPercent, E_MISPLACED_PERCENT)                       \
  X(UnopenedPercent, W_UNOPENED_PERCENT)                         \
  /* apt */                                                      \
  X(AptSyntax, E_APT_SYNTAX)                                     \
  X(AptUndefinedSymbol, E_APT_UNDEFINED_SYMBOL)                  \
  X(AptUnknownForm, E_APT_UNKNOWN_FORM)                          \
  X(AptNoSolution, E_APT_NO_SOLUTION)                            \
  X(AptArithmetic, E_APT_ARITHMETIC)                             \
  X(AptBadArgument, E_APT_BAD_ARGUMENT)                          \
  X(AptNotSupported, E_APT_NOT_SUPPORTED)                        \
  X(AptNoFini, W_APT_NO_FINI)                                    \
  /* CL files: CLDATA, NX CLSF, APT CL */                        \
  X(ClBadRecord, E_CL_BAD_RECORD)                                \
  X(ClBadArgument, E_CL_BAD_ARGUMENT)                            \
  X(ClBadArc, E_CL_BAD_ARC)                                      \
  X(ClNotSupported, E_CL_NOT_SUPPORTED)                          \
  X(ClTooLarge, E_CL_TOO_LARGE)                                  \
  X(ClIgnored, W_CL_IGNORED)                                     \
  /* simulate: the stock model, its tools, its checks */         \
  X(StockGridTooLarge, E_STOCK_GRID_TOO_LARGE)                   \
  X(RapidCutsStock, E_RAPID_CUTS_STOCK)                          \
  X(CutBelowFloor, E_CUT_BELOW_FLOOR)                            \
  X(SimToolDefaulted, W_SIM_TOOL_DEFAULTED)                      \
  X(SimMotionNotModeled, W_SIM_MOTION_NOT_MODELED)               \
  X(ShankRubsStock, E_SHANK_RUBS_STOCK)                          \
  X(HolderHitsStock, E_HOLDER_HITS_STOCK)                        \
  X(PlungeNotCentreCutting, W_PLUNGE_NOT_CENTRE_CUTTING)         \
  X(MaterialAboveTarget, W_MATERIAL_ABOVE_TARGET)                \
  /* job: job files, tool libraries, materials, cutting data */  \
  X(BadJob, E_BAD_JOB)                                           \
  X(UnknownJobKey, E_UNKNOWN_JOB_KEY)                            \
  X(JobUnknownTool, E_JOB_UNKNOWN_TOOL)                          \
  X(JobUnknownMaterial, E_JOB_UNKNOWN_MATERIAL)                  \
  X(JobUnknownOperation, E_JOB_UNKNOWN_OPERATION)                \
  X(JobMissingLayer, E_JOB_MISSING_LAYER)                        \
  X(JobNoToolFits, E_JOB_NO_TOOL_FITS)                           \
  X(JobNoCuttingData, E_JOB_NO_CUTTING_DATA)                     \
  X(BadToolLibrary, E_BAD_TOOL_LIBRARY)                          \
  X(BadMaterials, E_BAD_MATERIALS)                               \
  X(JobCuttingLimited, N_JOB_CUTTING_LIMITED)                    \
  /* job: the operations checked against the stock */            \
  X(JobOutsideStock, E_JOB_OUTSIDE_STOCK)                        \
  X(JobPartlyOutsideStock, W_JOB_PARTLY_OUTSIDE_STOCK)           \
  X(JobDeeperThanStock, E_JOB_DEEPER_THAN_STOCK)                 \
  X(JobCutsThroughStock, W_JOB_CUTS_THROUGH_STOCK)               \
  X(JobCutsBelowStock, W_JOB_CUTS_BELOW_STOCK)                   \
  X(JobHoleNotThrough, W_JOB_HOLE_NOT_THROUGH)                   \
  /* job: a bore and the hole it finishes */                     \
  X(JobPilotHole, E_JOB_PILOT_HOLE)

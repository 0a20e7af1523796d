// The esc scripting language. The parser is generated at build time (grammar/CMakeLists.txt)
// and used only by the compiler (compiler/parse.cpp), which turns the parse tree into an AST.
// The language is described for users in docs/language.md.
//
// Units: the lexer never produces UNIT; the compiler retypes an identifier that follows a
// number into UNIT before parsing when it is attached to the number (`60cm`, `60cn`) or is a
// known unit name (`0.5 m/s^2`), so `substeps 5 ir_rays 3` still reads as two settings.
grammar Esc;

tokens { UNIT }

script : decl* EOF ;

decl
  : importDecl
  | arenaDecl
  | robotDecl
  | behaviorDecl
  | fitnessDecl
  | controllerDecl
  | experimentDecl
  | libraryDecl
  | primitivesDecl
  | studyDecl
  ;

importDecl : IMPORT STRING ';'? ;

// ---- arenas -------------------------------------------------------------------------
arenaDecl : ARENA name=ident '{' arenaItem* '}' ;

arenaItem
  : kw=(SIZE | BOX) w=quantity X h=quantity ';'?                                  # arenaSize
  | CYLINDER AT point RADIUS r=quantity ';'?                                        # arenaCylinder
  | BLOCK AT point SIZE w=quantity X h=quantity (ANGLE a=quantity)? ';'?            # arenaBlock
  | WALL FROM p1=point TO p2=point (THICKNESS t=quantity)? ';'?                     # arenaWall
  | GOAL AT point ';'?                                                              # arenaGoal
  | START RANDOM ';'?                                                               # arenaStartRandom
  | START AT point (HEADING a=quantity)? ';'?                                       # arenaStartAt
  | LIGHT name=ident (AT point | ABOVE zone=ident) (HEIGHT h=quantity)? (INTENSITY i=quantity)? ';'?   # arenaLight
  | ZONE name=ident (CIRCLE RADIUS r=quantity | RECT w=quantity X h=quantity)
      AT (point | RANDOM) zoneFlag* ';'?                                            # arenaZone
  | SWEEP_CELL q=quantity ';'?                                                      # arenaSweepCell
  | REACH_RADIUS q=quantity ';'?                                                    # arenaReachRadius
  ;
zoneFlag : VISIBLE | INVISIBLE | RECHARGE ;

point : '(' x=quantity ',' y=quantity ')' ;

quantity : sign=('-' | '+')? NUMBER unit? ;
unit : UNIT ('/' UNIT ('^' NUMBER)?)? ;

// ---- robots -------------------------------------------------------------------------
robotDecl : ROBOT name=ident ('=' base=ident)? settingsBlock? ;
settingsBlock : '{' setting* '}' ;
// A list of quantities only where a setting takes one (`rangefinders [90deg, 0deg, -90deg]`),
// or of tuples (`ir_sensors [(68deg, 90deg), (43deg, 45deg)]`); a name (`ir_name prox`).
setting : key=ident (value | list=quantityList | word=ident) ';'? ;
value : quantity | ON | OFF | TRUE | FALSE ;
quantityList
  : '[' (quantity (',' quantity)*)? ']'
  | '[' quantityTuple (',' quantityTuple)* ']'
  ;
quantityTuple : '(' quantity (',' quantity)* ')' ;

// ---- behaviors ----------------------------------------------------------------------
behaviorDecl
  : BEHAVIOR name=ident '(' (ident (',' ident)*)? ')' '{' body=call ';'? '}'
  // Another experiment's evolved controller, frozen with the best genome over its runs.
  | BEHAVIOR name=ident '=' EVOLVED FROM EXPERIMENT exp=ident CONTROLLER ctl=ident ';'?
  ;
// A named group of behaviors; a member `avoid` of `library classical { ... }` is
// `classical.avoid` elsewhere, and the library's name in a supervisor's list stands for
// all its members in order. A word after the name marks the library: `useless` (reports
// draw its members apart from the useful ones).
libraryDecl : LIBRARY name=ident mark=ident? '{' behaviorDecl* '}' ;

call : fn=ident '(' (expr (',' expr)*)? ')' ;

// ---- fitness ------------------------------------------------------------------------
fitnessDecl : FITNESS name=ident '{' fitnessItem* '}' ;
fitnessItem
  : STEP ':' expr ';'?            # fitnessStep
  | STOP EPOCH WHEN expr ';'?     # fitnessStop
  // Terms added once at the end of each epoch, and of the evaluation, over its aggregates.
  | EPOCH ':' expr ';'?           # fitnessEpoch
  | EVALUATION ':' expr ';'?      # fitnessEvaluation
  // How a group's robots' terms make the group's (`over robots min`; mean by default).
  | OVER what=ident ':'? reduce=ident ';'?   # fitnessOver
  ;

// ---- controllers --------------------------------------------------------------------
controllerDecl : CONTROLLER name=ident '=' controllerExpr ';'? ;
controllerExpr
  // `neat(...)`: NEAT's network, its inputs and (classical) `-> wheels`; NEAT grows the rest.
  : net=(MLP | ELMAN | NEAT) '(' network ')'                                          # mlpController
  | SYMBOLIC '(' net=(MLP | ELMAN | NEAT) '(' network ')' ',' ACTIONS '[' ident (',' ident)* ']' ')'   # symbolicController
  | SUPERVISOR '(' net=(MLP | ELMAN | NEAT) '(' network ')' ',' BEHAVIORS '[' supervised (',' supervised)* ']' ')'   # supervisorController
  // A GP tree: its result (`wheels`, or a choice among actions or behaviors) and its primitives.
  | TREE '(' treeResult ',' PRIMITIVES prims=ident ')'                                 # treeController
  // A network per body of a group whose bodies read other sensors (docs/groups.md):
  // `per_body(khepera: cc, thymio2: cc_thymio)`, each a network controller with one head.
  | PER_BODY '(' bodyNetwork (',' bodyNetwork)* ')'                                   # perBodyController
  ;
bodyNetwork : body=ident ':' ctl=ident ;
treeResult
  : ACTIONS '[' ident (',' ident)* ']'
  | BEHAVIORS '[' supervised (',' supervised)* ']'
  | ident
  ;
supervised : ident ('.' member=ident)? ('(' (quantity (',' quantity)*)? ')')? ;
network : input (',' input)* ('->' layer)* ;
input : ident ('[' lo=NUMBER ('..' hi=NUMBER)? ']')? ;
layer : ident NUMBER? ;

// ---- primitive sets (genetic programming) -------------------------------------------
// Functions are operator symbols or function names, spaces or commas between them; a
// function name is a plain ID (never a keyword), so the word `terminals` ends the list.
primitivesDecl : PRIMITIVES name=ident '{' primItem* '}' ;
primItem
  : FUNCTIONS primFunction (','? primFunction)* ';'?           # primFunctions
  | TERMINALS primTerminal (',' primTerminal)* ';'?            # primTerminals
  ;
primFunction
  : op=('+' | '-' | '*' | '/' | '^' | '<' | '<=' | '>' | '>=' | '==' | '!=')
  | AND | OR | NOT | IF | ID
  ;
primTerminal
  : ident '(' lo=quantity ',' hi=quantity ')'                  # primErc
  | ident ('[' lo=NUMBER ('..' hi=NUMBER)? ']')?               # primObservable
  | quantity                                                   # primConstant
  | (TRUE | FALSE)                                             # primBool
  ;

// ---- experiments --------------------------------------------------------------------
experimentDecl : EXPERIMENT name=ident '{' expItem* '}' ;
expItem
  : ARENA ident ';'?                                                             # expArena
  // `robot khepera x 3`: a group of three; `robot khepera x 2, lit_khepera`: of two bodies
  // (docs/groups.md).
  | ROBOT groupMember (',' groupMember)* ';'?                                      # expRobot
  // Where a group's robots start (docs/groups.md): `formation line 10cm`, `formation circle
  // 15cm`, `formation at [(20cm, 20cm, 90deg), (40cm, 20cm, 90deg)]`; random by default.
  | FORMATION kind=ident (spacing=quantity | list=quantityList)? ';'?               # expFormation
  // `roles 3`: a genome per role, evolved together as one genome; robot i plays role i mod 3
  // (docs/groups.md). One role, the default, is the clonal team.
  | ROLES NUMBER ';'?                                                             # expRoles
  | EPOCHS NUMBER (X NUMBER STEPS)? ';'?                                          # expEpochs
  | STEPS NUMBER ';'?                                                             # expSteps
  // The fitness (the first objective), with the range its values lie in when declared.
  | FITNESS ident objRange? ';'?                                                  # expFitness
  // Further objectives, each a fitness declaration, in order after the fitness.
  | OBJECTIVE ident dir=(MAXIMIZE | MINIMIZE)? objRange? ';'?                     # expObjective
  // A behavior descriptor: an end term at each epoch's end (reduced over the epochs, by
  // mean unless `by` says otherwise) or, after `evaluation:`, once over the evaluation.
  // `over robots R`: a group's robots' values reduced by R (mean by default).
  | DESCRIPTOR name=ident ':' (EVALUATION ':')? expr objRange (BY reduce=ident)? (OVER what=ident over=ident)? ';'?   # expDescriptor
  // When an evaluation counts as a success: a test of the fitness, a further objective or a
  // descriptor, as measured (`success when reach_goal > -17.1875mm`).
  | SUCCESS WHEN obj=ident cmp=('<' | '<=' | '>' | '>=') threshold=quantity ';'?    # expSuccess
  // Each run ends at the generation of its first success (Lehman & Stanley's runs do).
  | STOP AT SUCCESS ';'?                                                          # expStopAtSuccess
  | EVOLVE ident ('(' (esOption (',' esOption)*)? ')')? (FOR NUMBER GENERATIONS)? ';'?   # expEvolve
  | RUNS NUMBER ';'?                                                              # expRuns
  | SEED NUMBER ';'?                                                              # expSeed
  // `CS8 as CS`: compared under another name, so that a study pairs it with the CS of
  // other conditions; `SC by cmaes`: evolved by that algorithm, not the experiment's default.
  | COMPARE compared (',' compared)* ';'?                                         # expCompare
  // Each run takes the best genome of the same run of another experiment (which runs
  // first): `evaluate` only evaluates it here; `start` evolves on from it.
  | kw=(START | EVALUATE) FROM EXPERIMENT ident ';'?                              # expStartFrom
  ;
groupMember : ident settingsBlock? (X NUMBER)? ;
objRange : IN '[' lo=quantity ',' hi=quantity ']' ;
esOption : ident ('[' lo=quantity ',' hi=quantity ']' | quantity)? ;
compared : ctl=ident (BY algo=ident)? (AS alias=ident)? ;

// ---- studies: conditions compared together ------------------------------------------
studyDecl : STUDY name=ident '{' studyItem* '}' ;
studyItem
  : CONDITIONS ident (',' ident)* ';'?                                           # studyConditions
  | CONDITION name=ident '=' exp=ident ('{' studySetting* '}')? ';'?              # studyCondition
  | SWEEP exp=ident '{' studySetting* '}' ';'?                                    # studySweep
  | RUNS NUMBER ';'?                                                              # studyRuns
  | SEED NUMBER ';'?                                                              # studySeed
  ;
// A `--set` key and its value in script syntax; in a sweep, a list of values `[a, b, ...]`
// (a range is itself a list of two numbers: `bounds [[-1, 1], [-2, 2]]`).
studySetting : key=settingKey studyValue ';'? ;
// `generations`, `robot.time_constant`; in a study, a setting of an experiment the
// condition depends on, named first (`energy.generations`, `energy.stop.generations`).
settingKey : keyPart ('.' keyPart)* ;
keyPart : ROBOT | ARENA | ident ;
studyValue
  : value | ident
  | '[' (studyValue (',' studyValue)*)? ']'
  ;

// ---- expressions (earlier alternatives bind tighter) ---------------------------------
expr
  : '(' expr ')'                                           # parenExpr
  | NUMBER unit?                                           # numberExpr
  | (TRUE | FALSE)                                         # boolExpr
  | ident '(' (expr (',' expr)*)? ')'                      # callExpr
  | ident '[' expr ']'                                     # indexExpr
  // `library.member`: a library's behavior, as `using(...)`, `share(...)`, `count(...)` read it.
  | ident '.' member=ident                                 # memberExpr
  | ident                                                  # nameExpr
  | <assoc=right> expr '^' expr                            # powExpr
  | op=('-' | '+') expr                                    # unaryExpr
  | expr op=('*' | '/') expr                               # mulExpr
  | expr op=('+' | '-') expr                               # addExpr
  | expr op=('<' | '<=' | '>' | '>=' | '==' | '!=') expr   # cmpExpr
  | NOT expr                                               # notExpr
  | expr AND expr                                          # andExpr
  | expr OR expr                                           # orExpr
  | IF expr THEN expr ELSE expr                            # ifExpr
  ;

// Words that are keywords in one place and ordinary names elsewhere.
ident
  : ID | X | STEPS | STEP | EPOCH | EPOCHS | STOP | WHEN | AT | RADIUS | SIZE | BOX | ANGLE
  | START | RANDOM | HEADING | CYLINDER | BLOCK | MLP | NEAT | SYMBOLIC | ACTIONS | FOR
  | GENERATIONS | RUNS | SEED | COMPARE | EVOLVE | LIGHT | ABOVE | HEIGHT | INTENSITY | ZONE
  | CIRCLE | RECT | VISIBLE | INVISIBLE | RECHARGE | SWEEP_CELL | REACH_RADIUS | ELMAN
  | SUPERVISOR | BEHAVIORS | ON | OFF | EVOLVED | FROM | EVALUATE | EVALUATION | TREE | FUNCTIONS | TERMINALS
  | CONDITIONS | CONDITION | SWEEP | AS | BY | OBJECTIVE | MAXIMIZE | MINIMIZE | DESCRIPTOR | IN | WALL | GOAL | TO | THICKNESS
  | SUCCESS | OVER | FORMATION | ROLES | PER_BODY
  ;

// ---- lexer --------------------------------------------------------------------------
IMPORT : 'import' ;
ARENA : 'arena' ;
ROBOT : 'robot' ;
BEHAVIOR : 'behavior' ;
FITNESS : 'fitness' ;
CONTROLLER : 'controller' ;
EXPERIMENT : 'experiment' ;
LIBRARY : 'library' ;
PRIMITIVES : 'primitives' ;
STUDY : 'study' ;
IF : 'if' ;
THEN : 'then' ;
ELSE : 'else' ;
AND : 'and' ;
OR : 'or' ;
NOT : 'not' ;
TRUE : 'true' ;
FALSE : 'false' ;

X : 'x' ;
STEPS : 'steps' ;
STEP : 'step' ;
EPOCH : 'epoch' ;
EPOCHS : 'epochs' ;
STOP : 'stop' ;
WHEN : 'when' ;
AT : 'at' ;
RADIUS : 'radius' ;
SIZE : 'size' ;
BOX : 'box' ;
ANGLE : 'angle' ;
START : 'start' ;
RANDOM : 'random' ;
HEADING : 'heading' ;
CYLINDER : 'cylinder' ;
BLOCK : 'block' ;
MLP : 'mlp' ;
NEAT : 'neat' ;
SYMBOLIC : 'symbolic' ;
ACTIONS : 'actions' ;
FOR : 'for' ;
GENERATIONS : 'generations' ;
RUNS : 'runs' ;
SEED : 'seed' ;
COMPARE : 'compare' ;
EVOLVE : 'evolve' ;
LIGHT : 'light' ;
ABOVE : 'above' ;
HEIGHT : 'height' ;
INTENSITY : 'intensity' ;
ZONE : 'zone' ;
CIRCLE : 'circle' ;
RECT : 'rect' ;
VISIBLE : 'visible' ;
INVISIBLE : 'invisible' ;
RECHARGE : 'recharge' ;
SWEEP_CELL : 'sweep_cell' ;
REACH_RADIUS : 'reach_radius' ;
ELMAN : 'elman' ;
SUPERVISOR : 'supervisor' ;
BEHAVIORS : 'behaviors' ;
ON : 'on' ;
OFF : 'off' ;
EVOLVED : 'evolved' ;
FROM : 'from' ;
EVALUATE : 'evaluate' ;
EVALUATION : 'evaluation' ;
TREE : 'tree' ;
FUNCTIONS : 'functions' ;
TERMINALS : 'terminals' ;
CONDITIONS : 'conditions' ;
CONDITION : 'condition' ;
SWEEP : 'sweep' ;
AS : 'as' ;
BY : 'by' ;
OBJECTIVE : 'objective' ;
MAXIMIZE : 'maximize' ;
MINIMIZE : 'minimize' ;
DESCRIPTOR : 'descriptor' ;
SUCCESS : 'success' ;
IN : 'in' ;
WALL : 'wall' ;
GOAL : 'goal' ;
TO : 'to' ;
OVER : 'over' ;
FORMATION : 'formation' ;
ROLES : 'roles' ;
PER_BODY : 'per_body' ;
THICKNESS : 'thickness' ;

ARROW : '->' ;
DOTDOT : '..' ;
DOT : '.' ;
LE : '<=' ;
GE : '>=' ;
EQ : '==' ;
NE : '!=' ;
LT : '<' ;
GT : '>' ;
PLUS : '+' ;
MINUS : '-' ;
STAR : '*' ;
SLASH : '/' ;
CARET : '^' ;
LPAREN : '(' ;
RPAREN : ')' ;
LBRACK : '[' ;
RBRACK : ']' ;
LBRACE : '{' ;
RBRACE : '}' ;
COMMA : ',' ;
SEMI : ';' ;
COLON : ':' ;
ASSIGN : '=' ;

NUMBER : [0-9]+ ('.' [0-9]+)? ([eE] [+-]? [0-9]+)? ;
ID : [a-zA-Z_] [a-zA-Z_0-9]* ;
STRING : '"' (~["\\\r\n] | '\\' ~[\r\n])* '"' ;

LINE_COMMENT : '//' ~[\r\n]* -> skip ;
BLOCK_COMMENT : '/*' .*? '*/' -> skip ;
// A `/*` with no `*/` after it: everything to the end of the file, no `*/` inside. Where a
// `*/` follows, BLOCK_COMMENT is the longer match. The compiler reports it at the `/*`
// (without it, the lexer read `/` and `*` and the parser said "found `/`").
UNTERMINATED_COMMENT : '/*' ( ~'*' | '*'+ ~[*/] )* '*'* ;
WS : [ \t\r\n\f]+ -> skip ;

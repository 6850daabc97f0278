"""What a request wants, read from a small general vocabulary: whether it adds or takes away
("take it out", "without the bin", "no hydrant"), and whether it asks for information ("which
...", "list the lanes", "I need the number of trees") or, however politely, for a change ("could
you add two cars?"). Read by the plan-versus-request check (request.py) and by the rule planner,
so that the two never disagree on what kind of request they hold.
"""

from __future__ import annotations

import re
from functools import cache

from drivetwin.tools.appearance import COLOURS
from drivetwin.worlds.catalog import catalog

# How things go, said of people or many things: "people there must have nowhere to ...", "cars keep
# getting hidden behind ...", "the kids can't see them": a state of affairs, not a request.
# Said of one ("the kid can't sleep unless it's dark", "students from the library want to sit outside"), it is
# who the request is for too, as is whoever wants or complains.
# What people are called, singular or plural: the catalog's words for a walker ("commuter", "jogger").
_PEOPLE_WORDS = tuple(f"{re.escape(w)}s?" for w in dict.fromkeys((*catalog()["pedestrian"].words, "cyclist")) if " " not in w)
HOW_THINGS_GO = re.compile(
    r"(?:(?:the|our|my|some|these|those|all the)\s+)?"
    # (people by any of the catalog's words for them: "the commuters at the stop say ...")
    rf"(?:{'|'.join(sorted(_PEOPLE_WORDS, key=len, reverse=True))}|drivers|children|folks|passengers|everyone|nobody|no one)\b[^,;.]*?"
    r"\b(?:must have|keep|keeps|can't|cant|cannot|couldn't|don't|doesn't|never|always|have nowhere|has nowhere|have no|struggle"
    r"|want|wants|would like|wish|wishes|complain|complains|complained"
    r"|reckon|reckons|say|says|said|think|thinks|feel|feels|would|will|could|might)\b"  # "the kids at the fountain reckon there's no shade"
    r"|\b[a-z]+s\s+(?:keep|kept)\s+(?:getting|being|on)\b")
# What others say, which the request follows ("residents complain the test car dawdles and holds the
# buses up. Have it do 30 mph."); not what they say should be ("people say there should be a bench").
REPORTED = re.compile(r"(?:residents|people|neighbou?rs|locals|parents|drivers|users|witnesses|they|he|she|someone|everyone"
                      r"|my \w+)\s+(?:complain(?:s|ed)?|say|says|said|tell|tells|told|report(?:s|ed)?|claim(?:s|ed)?"
                      r"|insist(?:s|ed)?|keep saying|mention(?:s|ed)?)\b(?![^.;!?]*\b(?:should|need|needs|must|ought|wants?)\b)")
# What a test is for, said as a case to see: "I want to see what happens if a child runs out in front of us".
WHAT_IF = re.compile(r"\b(?:see|know|find out|check|test)\s+what (?:happens|would happen|will happen|the ego does)\s+(?:if|when)\b")
# A place said to be empty as it is ("feels empty", "looks a bit bare"): a lack, not "empty it".
BARE_STATE = re.compile(r"\b(?:is|are|looks?|feels?|seems?|'s|too|so|very|rather|quite)\s+(?:\w+\s+){0,2}?(?:empty|bare|deserted|lifeless|barren)\b"
                        # "empty roads and the lamps buzzing": places described, never "empty the roads"
                        r"|(?<!\bthe )\b(?:empty|deserted|bare)\s+(?:roads|streets|lanes|lots|car parks|pavements|sidewalks)\b")
# "Too much" of a thing, not how far out of place one is ("the SUV is too much forward").
_TOO_MUCH = (r"(?<!not )too much(?!\s+(?:forwards?|back|backwards?|left|right|north|south|east|west|to the|towards?|in front|behind|ahead|away"
             r"|close|near|far|over|up|down)\b)")
REMOVE_WORDS = re.compile(
    r"\b(remove|delete|quit|g[ei]t rid(?: of)?|get shot of|take (?:(?:it|them|that|those|this|these) )?(away|out|off)|take (?:\w+ ){1,3}?away\b|tow (?:\w+ ){1,3}?away\b|take (?:\w+ ){1,3}?out\b(?! of\b)|(?:has|have|needs?|must|should|ought) to come (?:down|out)\b(?! (?:of|from|to|onto|into)\b)|(?:cut|chop|saw|take|tear|knock|pull) (?:\w+ ){0,3}?down\b|drop (?:the|all|those|these|every)\b(?![^,.;]*\b(?:at|by|near|next|in|on|off|into|onto|beside|behind|front|there|here|to)\b)|out of scope|clear (away|out|the|it|them|lot|parking lot)\b|no longer|don'?t want|do not want"
    r"|not (want|have|need|keep)|no more(?! (?:and|or|than)\b)|without(?! \w+ing\b)(?!\s+an?\s+(?!single\b))|fewer|less(?! in the way| of an? (?:obstacle|problem|nuisance|hazard|eyesore))|lose|eliminate|erase|discard|scrap"
    r"|strike (?=(?:the|that|those|these|all|both|it|them|every|most|some|half|one|two|three|\d+)\b)"  # "strike the set": off the stage
    r"|thin(?:s|ned|ning)? (?:\w+ ){0,2}out|cull\w*|prun(?:e|es|ed|ing)\b|weed(?:s|ed|ing)? (?:\w+ )?out"  # "them trees want thinning out"
    # "the rubble must not appear in the run", "the bin shouldn't be there": it should be gone
    r"|(?:must|should|may) ?n(?:o|')t (?:appear|exist|be (?:existing|there|here|present|visible|in (?:the )?(?:scene|run|simulation|world)))"
    r"|(?:does|do) ?n(?:o|')t need to (?:exist|be (?:there|here|in (?:the )?scene))|\bneeds? not (?:exist|be there)"  # "maybe it doesn't need to exist?"
    # "get that truck out of here", "take the cones out of the scene": out of the world, not to a place
    r"|(?:get|take|clear|move) (?:\w+ ){1,3}out of (?:here|there|the scene|the world|the simulation|sight|the picture)(?![^.;]*\b(?:into|onto|over to|somewhere (?:in|on|by|near))\b)"
    # "get those cars out of lot B": gone from there (moving them elsewhere says where to)
    # ("get the SUV out of the shot, somewhere in the other car park": a move, its place said after the comma)
    # "get a car or two out of it"; "get the SUV out of lot B, anywhere": moved, not taken away
    r"|(?:get|take|clear|pull) (?:\w+ ){1,5}?out of (?![^.;]*\b(?:into|to|onto|somewhere (?:in|on|by|near)|and (?:put|park|move)|anywhere"
    r"|elsewhere|somewhere else|some ?place else)\b)"
    # "pull the truck off site", "the cones can go offsite": out of the world
    r"|\boff[- ]?site\b|\boff (?:the )?(?:site|campus|set)\b(?![^.;]*\b(?:into|to|onto)\b)"
    # "pull the two cars from lot B": gone from there
    r"|pull (?:\w+ ){1,4}(?:from|off) (?=the|lot|parking|it|there)"
    # "clear most of the cars out of lot B", "clear the junk off the road": gone from there
    r"|clear (?:\w+ ){1,4}(?:out of|off|from)"
    r"|not (?:quite |nearly )?(?:so|as|that) many|too many|"
    + _TOO_MUCH +
    # "the seat and the bin should both go": gone, with no place or way to go to after it
    r"|(?:should|can|could|must|may|has to|have to|needs? to|(?:has |have |'s |'ve )?got to|gotta) (?:all |both |just )?go(?: away)?"
    r"(?=\s*(?:[,.;!?]|$|(?:i guess|i think|please|now|too|as well)\b)))\b"
    # "no hydrant", "actually, no people": it goes; "no wait, put it ...", "no worries" take nothing away
    r"|^(?:(?:actually|ok|okay|so|hmm+|oh|wait|um+|and|then|right|sorry)\W+)*no (?!(?:wait|hold|sorry|worries|problem|rush|idea|need to ask)\b)(?=[a-z])"
    r"|\b(?:they|it|those|these|that|this|the \w+)(?: \w+)? (?:were|was)(?:n't| not) (?:there|here)\b"  # "I'd rather they weren't there"
    # "I want no bins on campus", "there should be no signals at the crossroads": a scene without them
    # "the lamp shall be removed", "they should get taken away": the edit said in the passive
    r"|\b(?:be|been|being|get|gets|got)\s+(?:\w+ly\s+)?(?:removed|deleted|eliminated|erased|discarded|scrapped|taken (?:away|out|off)"
    r"|cleared (?:away|out)|got rid of)\b"
    # "the bench vanishes", "make them disappear", "poof": gone, as a story tells it
    r"|\b(?:vanish|disappear)(?:es|s|ed|ing)?\b(?! (?:into|in|against|among)\b)|\bpoof\b"  # not "it disappears into the grass": unseen
    r"|^\s*(?:(?:please|just|now|then|ok|so)\W+)*fell (?=(?:the|that|this|those|these|all|every|both|a|one|two|three)\b)"  # "fell the tree": cut down
    r"|\b(?:want|need|like|prefer|there (?:should|must|can|may|is to|are to) be|there'?s to be|(?:should|must) (?:be )?have) (?:no|zero)\b"
    r"|^(?:nobody|no one|no-one|nothing) (?=(?:should|must|may|can(?! (?:see|hear|spot|notice|find|reach|tell|make out)\b)|is|to|uses?|needs?|wants?)\b)"  # "nobody should be parked there"
    # "there's no need for the bench", "I don't think we need the sign anymore": not needed, so gone
    r"|\bno (?:need|use) for\b|\b(?:is|are)(?:n'?t| not) (?:needed|necessary|wanted) (?:any ?more|any longer)\b"
    r"|\b(?:don'?t|dont|do not|doesn'?t|does not) (?:really )?(?:think (?:we|i|you|they) )?(?:really )?need\b[^,.;!?]*\b(?:any ?more|any longer)\b"
    # "make sure there are no cars in lot B", "ensure nobody is standing at the bus stop": a scene without them
    r"|\b(?:make sure|ensure|see to it|check) (?:that )?(?:there (?:is|are|'s) )?(?:no|nothing|nobody|no one|no-one)\b"
    r"|\b(?:empty|free|devoid) of\b"  # "lot B must be completely empty of vehicles"
)
# People doing what they do ("people will eat lunch on that bench", "students often cut across"):
# who a statement is about, not a thing asked for.
# A memory the request is told beside ("back when I drove the number 9 ...", "in my day the bin stood ...",
# "reminds me of the night shift"): context, like a report, never what to do.
REMINISCED = re.compile(r"\b(?:back (?:when|in (?:my|the|those) days?|home|then|in the day)|in my day|in the old days|reminds? me of"
                        r"|(?:on|in|at|along) (?:the|my|our) old \w+|when i was (?:a|young|little|driving|working)|(?:i|we) used to|years ago"
                        r"|like (?:my|our) (?:old )?\w+)\b")  # "paint it red, like my old route bus": the speaker's own, no bus asked for
# A place or things wished livelier: "make the street busier", "liven them up".
# Asking for less going on: "make it a bit quieter out there", "calm the street down", "less busy".
QUIETER = re.compile(r"\b(?:quieter|calmer|less busy|not so busy|emptier|less crowded|less hectic|calm (?:it|things|the \w+) down)\b")
# A thing said to be missing: "there's no bin", "we have no benches", "the stop has no shelter" (said before the thing).
# A thing said after it to be gone ("the bench is missing", "the truck isn't there anymore"): a wish for it, not one there.
SAID_MISSING = re.compile(r"\b(?:missing|gone|absent|lost|nowhere|no longer|not there|isn'?t there|aren'?t there|not here|disappeared|vanished"
                          r"|anymore|any more)\b")
NONE_THERE = re.compile(r"\b(?:there(?:'s| is|s| are|re)|we(?:'ve| have)|(?:it|this|that|they) (?:has|have)|(?:has|have) got|got)\s+no\s+(?:[a-z]+\s+)?$")
LIVELIER = re.compile(r"\b(?:busier|more busy|livelier|more lively|liven (?:it |\w+ )?up|more going on|more life)\b")
HABITUAL = re.compile(r"\b(?:people|someone|somebody|everyone|students|drivers|pedestrians)\s+(?:will|often|usually|always|sometimes|tend to)\b")
# A thing something is forbidden to ("the robot mustn't drive through the fountain"): a constraint
# on it, not a thing asked for.
FORBIDDEN = re.compile(r"\s+(?:mustn'?t|must not|shouldn'?t|should not|can'?t|cannot|won'?t|may not)\b")
# Weather asked for a little: "a bit cloudy", "a touch of fog", "snow, though not too much".
_WEATHER_WORD = r"(?:rain\w*|snow\w*|fog\w*|drizzl\w*|showers?|mist\w*|cloud\w*|overcast)"
_HEDGE = r"(?:a\s?bit|a little|a touch|slightly|somewhat|mildly|just a bit|a tad|(?:not|no)\s+(?:too\s+|so\s+|very\s+)?much)"
WEATHER_HEDGED = re.compile(rf"\b{_HEDGE}\s+(?:of\s+)?{_WEATHER_WORD}"
                            rf"|\b{_WEATHER_WORD}[\s,]+(?:\w+[\s,]+){{0,3}}?{_HEDGE}(?!\s+(?:more|harder|heavier|stronger|thicker))\b")
# Fewer of a kind, not none: "not so many trees", "too many cones", "thin out the benches".
FEWER_WORDS = re.compile(r"\b((?:keep|leave) (?:just|only) (?:the )?(?:\d+|one|two|three|four|five|six|seven|eight|nine|ten)|(?:is|are|'s|would be) (?:plenty|enough)|fewer|less(?! in the way| of an? (?:obstacle|problem|nuisance|hazard|eyesore))|(?:do|does|did)(?:n't| not) (?:\w+ ){0,3}need (?:quite |nearly )?(?:so|as|that) (?:much|many)|not (?:quite |nearly )?(?:so|as|that) many|too many|" + _TOO_MUCH + r"|thin(?:s|ned|ning)? (?:\w+ ){0,2}out|cut down on|reduce)\b")
# How many of them to keep: "keep just two", "leave one of them" (the amount is group 1).
# "one is plenty", "two of them would be enough": as many kept as that.
KEEP_SOME = re.compile(r"\b(?:(?:keep|leave)\s+(?:just |only |me )?(?:the )?(?=(?:\d+|one|two|three|four|five|six|seven|eight|nine|ten)\b)"
                       r"|(?:all|every\w*|each)\s+(?:(?:of\s+)?(?:the|them|those|these)\s+)?(?:[a-z]+\s+){0,5}?(?:but|except(?: for)?|save|bar|apart from|other than)\s+"
                       r"(?:for\s+)?(?=(?:\d+|one|two|three|four|five|six|seven|eight|nine|ten)\b)"  # "all but one tree", "every lamp except two"
                       # "the vehicles in lot B, save for one, ...": a number set apart by commas
                       r"|(?:(?<=, )|(?<=,  ))(?:save for|except for|except|apart from|other than|bar)\s+"
                       r"(?=(?:\d+|one|two|three|four|five|six|seven|eight|nine|ten)\s*,)"
                       r"|(?=(?:\d+|one|two|three|four|five|six|seven|eight|nine|ten)(?: of (?:them|those|these))? (?:is|are|'s|would be|will be|will do)"
                       r" (?:plenty|enough|all (?:we|i) need)\b))(\d+|one|two|three|four|five|six|seven|eight|nine|ten)\b")
ADD_WORDS = re.compile(r"\b(add|(?<!any )more|another|extra|busier|fuller|create|spawn|insert|put|place|bring in|new)\b")

_QUESTION_START = re.compile(r"(?:^\s*|^[a-z ]{1,20}:\s*)(?:(?:so|ok|okay|well|hey|right|and|wait|hmm+|um+|uh+|erm|oh|quick question|roughly|approximately|about|just)\s*,?\s+)*(which|what|in which|in what|where|how|is there|are there|is the|are the|does|do any|who|whats|wheres|hows|whos"
                             r"|is anything|is any|is anyone|is anybody|is someone|is somebody|is nobody|are any|is something|has anything|has anyone|have any|do the"
                             r"|do (?:we|you|i) (?:have|see|got)|have (?:we|you) got|(?:we|you) got any|got any"  # "do we have any bikes"
                             # "is it dark yet", "is it raining": a state asked about; "is it possible to ..." asks for a change
                             r"|is it(?! (?:possible|ok|okay|alright|all right|fine|feasible|allowed|doable|worth|a good idea|too|time|ever)\b))\b"
                             # "the gates, where are they": the thing first, the question after it
                             r"|,\s*(?:where|what|which) (?:is|are) (?:it|they|those|these|them)\b")
# Asking for information inside a sentence of any mood ("could you tell me which ...", "I need
# the number of ...", "to know what a truck weighs"): a question, whatever the sentence opens with.
_INFO = re.compile(r"^\s*(?:query|lookup|look ?up|get|info|status|report)\s*:|(?<!(?<!pl)s )\b(tell me|show me|let me know|inform (?:me|us)|advise (?:me|us)|"
                   # "kindly state the weather", "please identify the tree closest to ...": asked to say, not to set
                   r"(?:^|(?:please|kindly|pls|now|could you|can you|would you)\s+)(?:state|identify|report|indicate|specify|name)\s+(?:the|which|what|where|how)|"
                   r"^\s*(?:please\s+)?report\b(?! (?:it|this|that) (?:as|to)\b)|"  # "Report one value: distance, ego to main gate": a look-up
                   r"tell (?:[a-z]+ ){1,2}(?:what|which|where|how|whether|if)|at what distance|how long is|"
                   # "say position of the hydrant", "say separation to the traffic ahead": radio for "tell me"
                   r"(?:^|[,:]\s*)say (?:the |your )?(?:position|location|separation|distance|heading|speed|weather|time|what|which|where|how)\b|"
                   r"(?:inventory|rundown|overview|summary|tally|head ?count|count|stock ?take|census|roll ?call) of|how many|how far|how much|(?:^\s*|\bthe |\btotal |\bwhat )number of|count of|list of|"
                   r"distance (?:between|from)|"
                   r"give (?:me|us) (?:a |an |the )?(?:rundown|overview|summary|names?|positions?|locations?|head ?count|count|tally|list)\b|"
                   r"(?:weights?|mass(?:es)?|dimensions|lengths?|widths?|heights?) of (?:the |a |an |both |each |all )|"
                   r"find out|check (which|what|where|how|wh?ether|if)|"
                   # "kindly advise the location of ...", "need suv_1's pose in the map frame": where something is
                   r"advise (?:me |us )?(?:of |on |as to )?the (?:the )?(?:location|position|whereabouts|distance|number)|"
                   # "coordinates of the nearest tree?", "req grid ref of the bin": where something is, asked bare
                   r"(?:^|(?:req|request|requesting|need|want)\s+)(?:the\s+)?(?:coordinates|position|location|whereabouts|grid ref(?:erence)?|pose"
                   r"|ids?|identifiers?|asset ids?) of\b(?![^.?!]*:)|"
                   # "the fire marshal needs hydrant data", "I need the bench details": what is known of a thing
                   r"\b(?:need|needs|want|wants|require|requires)\s+(?:the\s+|its\s+|their\s+)?(?:[a-z_0-9]+\s+){1,2}"
                   r"(?:data|details|info|information|coordinates|specs?)\b(?!\s+(?:to|should|must)\b)|"
                   r"'s (?:pose|position|coordinates|location|whereabouts|heading)(?!\s+(?:should|must|needs?|has|is to|ought|will|would|can|could|to)\b)|"
                   r"(?:write|note|jot|put) (?:it )?down (?:what|which|where|how|whether|if)|"  # "asked me to write down which lane ..."
                   # "I must record where those bikes were left", "point out the closest tree": said, shown, never moved
                   r"(?:note|record|log|mark) (?:where|which|what|how many)|point(?:s|ing)? out (?:the|which|what|where)|"
                   # "I'd like to confirm there are no cars in it", "just want to be sure there isn't one": verifying
                   r"(?:confirm|verify|double[- ]check|be (?:sure|certain)) (?:which|what|where|how)\b|"  # "kindly confirm which lane ..."
                   r"(?:confirm|verify|double[- ]check|be (?:sure|certain)) (?:that |wh?ether |if )?(?:there (?:is|are|was|were|'s)|"
                   r"there (?:isn'?t|aren'?t)|(?:the|it|they|nothing|none|no|all|every)\b)|"
                   # "the distance between them is to be reported": what is wanted is an answer
                   r"(?:is|are) to be (?:reported|measured|listed|counted|checked|confirmed|stated|given))\b"
                   # Read after any word (the lookbehind above is for "others tell me", a story):
                   # "the boss wants know where the bus is", "I want to know is it raining": a question after
                   # knowing, its "to" or its "whether" left out
                   r"|\b(?:to|i|we|me|wants?|wanna|wan) know (?:[a-z]+ )?(?:what|which|where|how|wh?ether|if|is|are|does|do|did|was|were|has|have)\b"
                   # "see if it is foggy", "see whether there are cones": whether a thing is so ("see if you can
                   # move it" asks for the moving)
                   # "for my notes I need the bench nearest the ego", "the log wants the car closest to it": which one is
                   r"|(?<!n't )(?<!not )(?<!longer )\b(?:need|needs|want|wants|require|requires|after)\s+the\s+(?:[a-z_]+\s+){1,3}?(?:nearest|closest|furthest|farthest)\b"
                   r"(?![^.;!?]*\b(?:moved|put|placed|brought|taken|to be|painted|gone|removed)\b)"
                   # "Distance check: from us to the north crosswalk, in metres": the figure asked, in its unit
                   r"|^\s*(?:[a-z ]{0,25}:\s*)?from\b[^.?!;]*\bto\b[^.?!;]*,?\s*in (?:metres|meters|feet|m|km|yards)\s*[.?!]*\s*$"
                   r"|\bsee (?:wh?ether|if) (?!(?:you|u|we|i)\b)|\bremind (?:me|us) (?:again )?(?:what|which|where|how|wh?ether|if)\b"
                   # doubt about what is so: "I was wondering if there's a bin", "can't remember whether I parked it
                   # in lot A", "not sure if the hydrant is still there" (wondering whether we could is a request)
                   # ("I wonder if the SUV could head to lot A?" wishes it done: see _POLITE)
                   r"|\bwonder(?:ing|ed)? (?:if|wh?ether) (?!(?:you|u|we|i|someone|somebody|anyone)\b)(?![^.?!]*\b(?:could|might|would|can)\b)"
                   r"|\b(?:can'?t|cannot|don'?t|do not|couldn'?t) (?:remember|recall) (?:if|wh?ether|which|where|what|how)\b"
                   r"|\bnot (?:sure|certain) (?:if|wh?ether) (?!(?:you|u|we|i)\b)|\b(?:no|any) idea (?:if|wh?ether)\b"
                   # "can you see any pedestrians", "do we spot anything on the road": what is there, looked at
                   r"|^\s*(?:(?:so|ok|okay|hey|and|now)\s+)?(?:can|could|do|does|did)\s+(?:you|u|we|i|the ego)\s+(?:see|spot|notice|make out)"
                   r"\s+(?:any|anything|anyone|anybody|a|an|the|some|how|if|whether|where|which|what)\b")
# Imperatives that ask for information ("list the lanes", "could you find the hydrant"): questions
# in the mood of a command, whatever the politeness around them.
_LOOKUP = re.compile(r"^(?:[a-z0-9 '-]{1,25}:\s*)?(?:(?:please|can you|could you|would you|will you|pls)\s+)?"  # "Before places: list ..."
                     r"(list|find|locate|count|search|look up|look for|identify|name the|describe|show|measure|work out)\b")
# A request put politely, at the start of the sentence or of a clause ("..., could you add two
# cars?", "could the bus go ..."): a command even when it ends with a question mark.
# Commands a hedge may come before or after ("maybe slow it down a bit?", "angle it a bit, maybe?").
_HEDGED_VERBS = ("add|put|drop|place|move|make|set|remove|take|get|give|turn|paint|park|bring|have|let'?s|slow|speed|angle|nudge|shift"
                 "|rotate|lose|ditch|swap|stop|send|clear|delete|thin|tidy|space|spread|line|fill|trim|cut|replace|change|brighten|darken")
_POLITE = re.compile(r"(?:^|[,.;:!-]\s*|\b(?:and|so|but|then)\s+)(?:can|could|would|will|might) (?:you|we|i)\b|^\s*please\b(?!\s*,?\s*(?:where|what|which|how|who|is there|are there)\b)"
                     # "could there be a couple of people at the stop?": a wish for what should be there
                     r"|(?:^|[.!;,\-\u2013\u2014]\s*)(?:can|could) (?:there|someone|somebody) be\b"
                     # "could it maybe have another car next to it?": a wish for it (not "could it have been moved?")
                     r"|(?:^|[.!;,\-\u2013\u2014]\s*)(?:can|could) (?:it|they|we) (?:maybe |perhaps |please |just )?have (?!been\b|gone\b|moved\b)"
                     # "could someone wander across the north crossing?": someone asked to do it, not whether anyone is
                     r"|(?:^|[.!;,\-\u2013\u2014]\s*)(?:can|could|would) (?:someone|somebody|anyone|anybody) (?:please |maybe |just )?"
                     r"(?:walk|wander|stroll|amble|cross|run|jog|stand|wait|drive|ride|cycle|go|come|head|pull|park)\b"
                     # "maybe drop a car by the library?": a suggestion, hedged
                     # (any sentence of it: "Let the ego race around. Maybe slow it down a bit?"), and a command hedged
                     # after it ("angle it a bit, maybe?") or put as a dare ("would it kill you to add a bin?")
                     rf"|(?:^|[.!;?,\-\u2013\u2014]\s*)(?:maybe|perhaps|how about|what about|why not)\s+(?:just\s+)?(?:{_HEDGED_VERBS})\b"
                     rf"|(?:^|[.!;?]\s*)(?:just\s+)?(?:{_HEDGED_VERBS})\b[^.!?]*,\s*(?:maybe|perhaps|possibly)\s*\?"
                     r"|\bwould it (?:kill|hurt) (?:you|anyone|ya) to\b"
                     # "could the second car go in lot A?": a wish for where a thing should be
                     r"|(?:^|[.!;?]\s*)(?:can|could) (?:the|that|this|our) (?:\w+ ){1,2}(?:go|be|move|stand|sit|start|park|drive|face|turn|get|come|disappear|vanish|leave)\b"
                     # "might the ego proceed more gently?", "may the lot B entrance be made safer?" (not "might the bus be in lot B?")
                     r"|(?:^|[.!;?]\s*)(?:might|may) (?:the|that|this|our) (?:\w+ ){1,3}?(?:go|move|proceed|drive|park|turn|face|leave"
                     r"|be (?:made|moved|painted|put|placed|turned|set|changed|shifted|taken|removed|slowed))\b"
                     # "the car you just put there, could it go forward?": the same wish for a thing named first
                     r"|(?:^|[,.;:!?-]\s*)(?:can|could) (?:it|they) (?:\w+ )?(?:go|move|stand|sit|start|park|drive|come|turn|shift|look|be|get|face"
                     r"|disappear|vanish|leave)\b"
                     # "maybe the ego could... back up?", "perhaps the hydrant could live by JTEKT?", "could the bin shift
                     # east?", "I wonder whether the parked cars could all go?": a wish for what a thing should do, hedged
                     # (not what it is able to do: "could the truck fit in lot A?")
                     r"|(?:^|[.!;?]\s*)(?:(?:maybe|perhaps|possibly|so|i wonder (?:whether|if))[,\s]+)?(?:(?:can|could|might) )?"
                     r"(?:the|that|this|our|those|these|someone|somebody) (?:[\w'-]+ ){0,2}?(?:(?:could|might|may)(?: \w+ly| all| both| just)?(?:\s*\.+\s*|\s+))?"
                     # (a word straight after "the" names the thing: "the stop sign could ...")
                     r"(?<!\bthe )(?:go|be|move|stand|sit|start|park|drive|face|turn|get|come|disappear|vanish|leave|live|shift|back up|reverse"
                     r"|cross|walk|change|slow|speed|stop|brake|wait|head)\b(?! (?:in|into|through|under|past) (?:it|there|here)\b)"
                     # "maybe it doesn't need to exist?": a wish it were gone, hedged
                     r"|(?:^|[.!;?]\s*)(?:maybe|perhaps)[,\s]+(?:it|they|that|this|the \w+) (?:does|do) ?n(?:o|')t need to\b"
                     # "maybe it could go somewhere?": the same wish said of the thing just spoken of
                     r"|(?:^|[.!;?]\s*)(?:maybe|perhaps|possibly)[,\s]+(?:it|they) (?:could|might) (?:\w+ly )?"
                     r"(?:go|be|move|stand|sit|park|drive|face|turn|come|leave|live|shift|back up|reverse|slow|speed|stop|wait|head)\b")


# English's ways of wrapping a request in a question ("is it possible to park ...", "any chance we
# could have ...", "would you mind adding ...", "I was wondering if you could ..."): a command,
# unless what is wrapped is itself a request for information ("is it possible to tell me ...").
# How many of a thing there should be, changed: "increase the number of benches", "reduce the count of cones".
_AMOUNT_CHANGED = re.compile(r"\b(?:double|triple|increase|reduce)\s+the\s+(?:number|count|amount)\s+of\b")
_NOT_INFO = r"(?!tell|say|know|see|find|check|count|list|show|measure)"
_WRAPPED = re.compile(
    rf"\b(?:is it|would it be|will it be|is that) (?:at all )?possible (?:for (?:you|us|me) )?to {_NOT_INFO}\w+"
    rf"|\b(?:any|some) (?:chance|way) (?:that )?(?:you|we|i|someone) (?:could|can|might|would) {_NOT_INFO}\w+"
    rf"|\bis there (?:any|a|some) (?:way|chance) (?:to|of) {_NOT_INFO}\w+"  # "is there any way to make the ego blue?"
    r"|\b(?:would|do) you mind (?!telling|saying|checking|counting|listing|showing)\w+ing\b"
    rf"|\bwonder(?:ing)? (?:if|whether) (?:you|we|i) (?:could|can|might) {_NOT_INFO}\w+"
    rf"|\bdo you think (?:you|we) (?:could|can) {_NOT_INFO}\w+")


# A clause saying why ("... so traffic can flow again", "... so that the ego has to stop", "in
# order to test the wipers"): the reason for a request, not a second request.
# A want said as what would do good, ending its clause or before a place ("so maybe two benches would
# help", "a couple of bins might be handy by the gate"): what is asked for, never a reason.
WOULD_HELP = (r"(?:would|could|might|may)(?: \w+ly)? (?:help|do the trick|be (?:\w+ )?(?:nice|good|great|handy|useful|welcome|ideal))"
              r"(?=\s*(?:[,.;!?]|$|(?:here|there|too|i think|i reckon|i guess|by|at|near|next to|beside|around|outside|in|on)\b))")
_REASON = re.compile(
    r",?\s+(?:so that|so as to|in order to|in order that|so)\s+(?![^.;!?]*\b" + WOULD_HELP + ")"
    # "fog so thick you can barely see": a degree said of the weather or a thing, not a reason after it
    r"(?!(?:very |really )?(?:thick|dense|heavy|hard|strong|bad|dark|bright|light|thin|much|many|few|little|foggy|misty"
    r"|wet|cold|low|high|fast|slow|close|far|big|small)\b)"
    r"(?:(?:the |a |our |we |they |it |cars |traffic |people )?(?:[a-z'-]+\s+){0,2}\w*\s*)?"
    # "... so people can rest, and a litter bin beside it": the reason ends where a second thing is asked for
    r"(?:can|could|will|would|may|might|won'?t|can'?t|cannot|doesn'?t|don'?t|has to|have to|gets?|is|are)\b(?:(?!,?\s+and\s+(?:a|an|some|two|three|\d+)\s)[^.;!?])*"
    # "... so that it blocks oncoming traffic": whatever follows "so that" says why
    r"|,?\s+(?:so that|in order that)\s+[^.;!?]*"
    # "... so nobody drives into it", ", to keep cars off the forecourt": who is kept from what, why
    r"|,?\s+so\s+(?:nobody|no one|nothing|no cars?|no traffic|everyone|everybody|drivers|cars|traffic)\s+[a-z']+\b[^.;!?]*"
    r"|,?\s+(?:to|so as to|in order to)\s+(?:keep|stop|prevent|protect|warn|calm|avoid|ensure)\s+[^.;!?]*"
    # "... across the crossing while the kids watch": what goes on meanwhile is no part of the request
    r"|,?\s+while\s+(?:the|a|an|our|my|some|everyone|everybody|people|they)\b[^.;!?,]*(?=[.;!?]|$)"
    # "... on the road to slow people down": who is slowed is no thing asked for
    r"|,?\s+(?:to|so as to|in order to)\s+slow\s+(?:down\s+)?(?:the\s+)?(?:people|drivers|cars|traffic|vehicles|everyone|everybody)\b[^.;!?]*",
    re.IGNORECASE,
)


# A reason said first and the request after it ("I want to see if the wipers cope, so give me
# rain"): the words before ", so" followed by a command say why.
_REASON_FIRST = re.compile(
    r"^[^.;!?]*?,\s*(?:and\s+)?so\s+(?=(?:please\s+|just\s+|(?:can|could|would) you\s+)?(?:give|make|add|put|set|let|"
    r"turn|bring|place|create|remove|take|move|get|start|switch|change|clear|park|spawn|drop|line|block|close|fence|"
    r"ring|surround|cordon|mark|have|let|paint|rotate|turn|slow|speed)\b)",
    re.IGNORECASE,
)

# A clause saying why with "because" or "since", after the request ("..., because the shadows at noon
# look wrong") or before it ("Because cyclists come down Campus Drive, the sign should stand ..."):
# why, not what; its things and times are not the request's.
_BECAUSE = re.compile(r"(?:,\s*|\s+)(?:because|since|'?cause|cos)\b[^.;!?]*", re.IGNORECASE)
_BECAUSE_FIRST = re.compile(r"^\s*(?:because|since|as)\b[^,.;!?]*,\s*(?=\S+(?:\s+\S+){2})", re.IGNORECASE)

_POINTS_BACK = re.compile(r"\b(it|its|there|them|they|their|that|those|these|this)\b", re.IGNORECASE)


# A label pasted with the request ("JIRA-412: ...", "[QA-7]", "ticket 31:"): it names the task,
# it is not a number of things or a word to understand.
_LABEL = re.compile(r"(?:^|(?<=\s))\[?[A-Za-z]{2,}-\d+\]?:?(?=\s|$)|\bticket\s*#?\s*\d+\s*:", re.IGNORECASE)
# A bug report's parts: "Steps:" or "Summary:" heads the request; "Expected: ..." restates its outcome, which is
# no second request ("Steps: turn bench_1 90 degrees. Expected: bench turned 90 deg").
_STEPS = re.compile(r"^\s*(?:steps?(?: to reproduce)?|repro|action|request|task|summary|title|subject)\s*:\s*", re.IGNORECASE)
_EXPECTED = re.compile(r"(?:^|(?<=[\s.;,]))(?:expected(?: result| outcome| behaviou?r)?|expectation|actual(?: result)?"
                       r"|acceptance(?: criteria)?)\s*:.*$", re.IGNORECASE | re.DOTALL)
# A ticket headed by a few words and then its acceptance criteria ("Summary: cone line lot B / Acceptance: 5 cones,
# one line, 3 m spacing, inside parking lot B"): the criteria say what to build, the heading only names it.
_TICKET = re.compile(r"^\s*(?:summary|title|subject)\s*:\s*(?P<head>[^/\n]+?)\s*(?:/|\n|;)\s*"
                     r"(?:acceptance(?: criteria)?|expected(?: result| outcome)?)\s*:\s*(?P<outcome>.+)$", re.IGNORECASE | re.DOTALL)
TICKET_HEAD_WORDS = 5


def _ticket_outcome(text: str) -> str:
    """A ticket's criteria in place of its few-word heading, the heading kept after them in brackets ("bench stands at
    the JTEKT entrance (move bench_1)"); any other text as it is."""
    said = _TICKET.match(text)
    if said is None or len(said.group("head").split()) > TICKET_HEAD_WORDS or asks(said.group("head").lower()):
        return text  # "Summary: what is at the crossroads": the heading asks, and the criteria only restate it
    head, outcome = said.group("head").strip(), said.group("outcome").strip()
    if not _TICKET_DETAIL.search(outcome.lower()) or _TICKET_DETAIL.search(head.lower()):
        return text  # the criteria add no place or figure the heading lacks ("any one of the cars removed")
    return f"{outcome} ({head})"


# What a ticket's criteria add to its heading: a figure, or a place something stands at.
_TICKET_DETAIL = re.compile(r"(?<![\w])\d|\b(?:at|in|inside|into|to|near|by|beside|next to)\s+(?:the\s+)?(?!night|noon|dusk|dawn|midnight|day)[a-z]")


# A tag that turns a request into a question only in form ("let's take it away, shall we?").
_TAG = re.compile(r",?\s*(?:shall we|will you|won'?t you|would you|could you|can you|ok|okay|right|yeah|alright)\s*\?\s*$",
                  re.IGNORECASE)
# A wish said as a cleft sentence ("What I'm after is a ring of cones", "what this scene is
# missing is traffic"): the words after its "is" are what is wanted. A verb of wanting comes
# before that "is"; a question ("what benches are near it") has none, or ends with a question mark.
_CLEFT = re.compile(r"^\s*what (?:i|we|you|they|it|i'm|we're|i'd|we'd|(?:the|this|that|our|my) [a-z]+)(?: [a-z']+){0,2}? "
                    r"(?:want|wants|need|needs|like|after|missing|lacks|lacking|mean|meant|have in mind|looking for|love"
                    r"|expect|expected|imagine|envisage|envision|prefer)(?: [a-z]+)? (?:is|are)\s+(?=[^?]*$)", re.IGNORECASE)
# An edit said as a noun ("Elimination of every litter bin is requested", "relocation of the bench
# to the library is required"): the verb it names, without the words that only ask for it.
_NOMINAL = {"removal": "remove", "elimination": "remove", "deletion": "delete", "addition": "add",
            "placement": "place", "relocation": "move", "rotation": "turn", "repainting": "paint"}
_NOMINAL_EDIT = re.compile(rf"^\s*(?:the )?({'|'.join(_NOMINAL)}) of\b", re.IGNORECASE)
_ASKED_FOR = re.compile(r"\s+(?:is|are) (?:now )?(?:requested|required|needed|wanted|expected|desired)\b", re.IGNORECASE)
# A layout named as a spec's heading ("Ring: 6x cones around the rubble"): a ring of them, one clause.
_LAYOUT_HEADING = re.compile(r"^\s*(ring|circle|line|row|grid)\s*:", re.IGNORECASE)


# A clause that names what is *not* meant ("..., not the ego", "but not the west ones", "except
# the one by the bench", "rather than in the car park", "instead of sitting there"): the request
# without it says what to do; the things it names are excepted (see `excepted`). "Instead of the
# bin" is left alone: it asks for a swap, the bin included.
_DETERMINER = r"(?:the|that|this|those|these|a|an|any|my|our|its|their|his|her|ego\b|[a-z_]+_\d+)"  # or an id
_CONTRAST = re.compile(
    rf"(?:,\s*(?:but\s+|and\s+)?|\s+but\s+)(?:not|never)\s+(?=(?:(?:way|right|all the way|over|out|down|up|somewhere)\s+){{0,2}}"
    rf"(?:{_DETERMINER}|in|at|on|by|near|next|beside|outside)\b"
    r"|(?:\d+(?:\.\d+)?|a few|several|so|that|too)\s*(?:m|metres?|meters?|feet|ft|far|away)\b)"
    # (or one named by its number: "all the trees except tree 3")
    rf"|\s+(?:except(?:\s+for)?|other\s+than|apart\s+from|excluding|save\s+for)\s+(?={_DETERMINER}|[a-z]+(?:\s[a-z]+)?\s(?:number\s|no\.?\s|#)?\d+\b)"
    # "remove the cars from lot B, but keep the SUV": what is kept is excepted
    rf"|,?\s+but\s+(?:keep|leave|spare)\s+(?={_DETERMINER})"
    # "rm: the lights - keep stop sign", "...; keep the SUV": a terse keep after a dash or a semicolon
    r"|\s*(?:[;\u2013\u2014]|\s-)\s*(?:but\s+)?(?:keep|leave|spare)\s+(?=[a-z])"
    # "paint the bench green and leave the bin as it is": what is left alone is excepted
    rf"|,?\s+and\s+(?:keep|leave)\s+(?={_DETERMINER}\b[^,.;]*\b(?:as (?:it|they) (?:is|are)|alone|untouched|where (?:it|they) (?:is|are)|in place|be)\b)"
    r"|\s+rather\s+than\s+(?=[a-z])"
    # "remove the cars from lot B, the SUV should stay": what stays is excepted
    # (or a sentence of its own that says no more: "Remove passenger_car_1 and passenger_car_2. The SUV stays.";
    # "... . The bin needs to stay there." says where it should be)
    rf"|[.;!]\s+(?={_DETERMINER}\s+[a-z_ ]+?\s+(?:stays?|remains?)\s*(?:[.!;]|$))"
    # ("..., but the bench must keep": "keep" with nothing after it to keep is "stay")
    rf"|,\s+(?:but\s+)?(?={_DETERMINER}\s+[a-z_ ]+?\s+(?:(?:should|must|can|will|is to|has to)\s+(?:stay|remain|be left|be kept"
    r"|keep\b(?!\s+(?:the|a|an|it|them|this|that|its|their|on|going|\w+ing)\b))"
    r"|(?:it\s+|they\s+)?(?:stays?|remains?)(?:\s+(?:where|as|put|there|here|please)\b|\s*(?=[.!;])|\s*$))\b)"  # "..., the truck stays", "the truck it stay"
    r"|\s+instead\s+of\s+(?=(?:in|at|on|by|near)\b|\w+ing\b)",
    re.IGNORECASE,
)
# Where a contrast clause ends: the next punctuation, a dash between clauses, or the colour the
# request ends on ("paint every car except the ego blue": the ego is excepted, blue is asked).
_CONTRAST_END = re.compile(r"\s+[-\u2013\u2014]\s+|[,.;!?]|$"
                           rf"|\s+(?:(?:to|in)\s+)?(?:{'|'.join(COLOURS)})\b(?=(?:\s+(?:please|pls|too|now|instead))?\s*[.!?]*\s*$)")


# What is kept said first, then all the rest acted on: "keep the trees, remove everything else near the fountain".
_KEPT_FIRST = re.compile(rf"^\s*(?:please\s+)?(?:keep|leave|spare)\s+(?={_DETERMINER}\b)", re.IGNORECASE)
_THE_REST = re.compile(r"\b(?:everything|anything|all)\s+else\b|\bthe (?:rest|others)\b", re.IGNORECASE)
# "but" after a word for every one of them is "except": "everything at the stop but the bench".
_ALL_BUT = re.compile(rf"\s+but\s+(?={_DETERMINER}\b)", re.IGNORECASE)
_EVERY = re.compile(r"\b(?:everything|anything|all|every|each)\b[^,.;!?]*$", re.IGNORECASE)


# What is kept or said to stay, then what to do: "keep the bench but lose the bin", "the bench can stay, get rid of the bin".
_STAYS_FIRST = re.compile(rf"^\s*(?={_DETERMINER}\s+[a-z_ ]+?\s+(?:(?:can|should|must|will|may)\s+)?(?:stays?|remains?|is fine|is ok|is okay)\b)",
                          re.IGNORECASE)
_THEN_ACT = re.compile(r"\s*(?:,\s*(?:but|and|though|while)?|\s(?:but|and|though|while))\s+(?:(?:just|only|please|do)\s+)?", re.IGNORECASE)


def _kept_then_acted(text: str) -> tuple[int, int, int] | None:
    """The contrast of a thing kept said before the request ("keep the bench but lose the bin"):
    the thing is excepted when a command follows it."""
    kept = _KEPT_FIRST.match(text) or _STAYS_FIRST.match(text)
    if kept is None:
        return None
    for then in _THEN_ACT.finditer(text, kept.end()):
        if commands(text[then.end() :].lower()):
            thing = _STAY_TAIL.sub("", text[kept.end() : then.start()]).split()
            # the thing alone ("keep the SUV moving" is a request of its own): an id, or ends on a catalog word
            if 1 <= len(thing) <= 4 and (re.fullmatch(r"[a-z_]+_\d+", thing[-1]) or (len(thing) > 1 and thing[-1].lower().rstrip("s") in _thing_words())):
                return 0, kept.end(), then.start()
            return None
    return None


# How a thing said first stays: "(the bench) can stay", "(the bin) is fine".
_STAY_TAIL = re.compile(r"\s+(?:(?:can|should|must|will|may)\s+)?(?:stays?|remains?|is fine|is ok|is okay)\b.*$", re.IGNORECASE)


@cache
def _thing_words() -> frozenset[str]:
    """The last words of the catalog's names for things ("bin", "light", "car"), singular."""
    return frozenset(n.replace("_", " ").split()[-1].lower().rstrip("s") for c in catalog().values() for n in (c.name, *c.synonyms))


def _contrasts(text: str) -> list[tuple[int, int, int]]:
    """(start, start of the excepted words, end) of each contrast clause after the request's first words."""
    out = []
    kept = _KEPT_FIRST.match(text)  # "keep the trees, remove everything else": the trees are excepted
    if kept is not None and _THE_REST.search(text, kept.end()) and (end := _CONTRAST_END.search(text, kept.end())) is not None:
        out.append((0, kept.end(), end.start()))
    elif (first := _kept_then_acted(text)) is not None:
        out.append(first)
    found = [*_CONTRAST.finditer(text), *(m for m in _ALL_BUT.finditer(text) if _EVERY.search(text[: m.start()]))]
    for m in sorted(found, key=lambda m: m.start()):
        if len(text[: m.start()].split()) < 2:
            continue  # "Hmm, not the bus - the truck": a correction, said first, stays as it is
        end = _CONTRAST_END.search(text, m.end())
        out.append((m.start(), m.end(), end.start() if end else len(text)))
    return out


# A greeting, thanks or sign-off said as a clause of its own ("Good afternoon.", "hi there,", "Thank
# you kindly, Margaret."); "good night" is left alone: it may ask for the night.
_SALUTATION = re.compile(
    r"(?:^|(?<=[.!?]))\s*(?:good\s+(?:morning|afternoon|evening|day)|hello|hi|hey|hiya|greetings|dear\s+\w+"
    r"|(?:many\s+)?thanks?(?:\s+you)?(?:\s+(?:so\s+much|kindly|very\s+much|in\s+advance|a\s+lot))?|cheers|(?:kind\s+|best\s+)?regards"
    # a sentence that only acknowledges the last turn: "Sweet.", "Nice one!", "Sure, ..."
    r"|sweet|cool|nice(?:\s+one)?|great|awesome|brilliant|perfect|lovely|excellent|sorted|ta|alright|sure)"
    r"(?:\s*,?\s+(?:there|all|everyone|team|folks|[a-z]+))?\s*(?:[,.!]+|$)"
    # the one spoken to, called by a radio station's name or the machine's: "Tower, ...", "Control: ..."
    r"|^\s*(?:tower|ground|control|base|approach|computer|system|drivetwin|sim|simulator)\s*[,:]"
    # the one spoken to, called so at the end of a sentence: "Ditch like half of those, bro."
    r"|,\s*(?:bro|bruh|dude|mate|man|boss|buddy|pal|fam|guys|folks|lads|sir|ma'am)\b(?=\s*(?:[.!?]|$))", re.IGNORECASE)


def without_salutations(text: str) -> str:
    """`text` without the clauses that only greet, thank or sign off."""
    return _SALUTATION.sub(" ", text).strip()


def excepted(text: str) -> list[str]:
    """The things a request says it does not mean ("remove the cars, not the ego" -> ["the ego"])."""
    return [_STAY_TAIL.sub("", text[said:end]).strip() for _, said, end in _contrasts(text) if text[said:end].strip()]


def without_contrast(text: str) -> str:
    """`text` without the clauses naming what is not meant (`excepted` reads those)."""
    for start, _, end in reversed(_contrasts(text)):
        text = text[:start] + text[end:]
    return text


# A slip taken back as it is said: "2 m east - sorry, west", "add three, no wait, two cones", "paint
# the bench - sorry, the bin - red", "blue, I mean green", "off - no, on", "car 1, or actually car 2".
_TAKEN_BACK = re.compile(r"\s*(?:[,;-]|--|\u2013|\u2014|\.\.\.)?\s*\b(?:sorr?y|soz|no wait|wait no|i mean|i meant|oops|or rather|"
                         r"or actually|scratch that|correction)\b[,:]?\s+(?:[-\u2013\u2014]\s*)?"
                         # "three cones, make that four" (never "... our car. Make that child cross")
                         r"|\s*(?:[,;]|(?<=\s)-|--|\u2013|\u2014)\s*make that\b[,:]?\s+"
                         r"|\s*(?:[,;.]|(?<=\s)-|--|\u2013|\u2014)\s*no(?:\s*(?:[,;.!:]|--|\u2013|\u2014)|\s+(?:sorr?y|soz)\b[,:]?)\s*", re.IGNORECASE)
# The kinds of word a correction swaps, each a pattern for one word; anything else is a thing named with an article.
_SWAPPED_KINDS = (
    r"\d+(?:\.\d+)?|one|two|three|four|five|six|seven|eight|nine|ten|eleven|twelve|twenty",
    r"north|south|east|west|left|right|forward|forwards|back|backwards|ahead|behind|up|down",
    r"on|off",
    "|".join(COLOURS),
)
# Words a correction shares with what it corrects that say nothing about where it goes.
_UNPLACED = frozenset({"the", "a", "an", "one", "ones", "just", "only", "it", "them", "that", "this", "those", "to", "of"})
# Openers of a correction that is a request of its own besides commands() ("half - no, leave just two").
_RESTART = re.compile(r"^(?:just\s+)?(?:leave|keep|have|let|give|stop|start)\b")
# Words after a correction mark that correct nothing ("..., I mean, sorry.").
_NOT_CORRECTIONS = frozenset({"sorry", "sory", "soz", "oops", "i mean", "thanks", "please", "pls"})
# Corrections taken back in turn ("circles, no, figure eight - no, just circles") are read this many deep.
_SLIPS = 3


def without_slip(text: str) -> str:
    """`text` with each word taken back replaced by its correction ("move the bench 2 m east - sorry,
    west" is "move the bench 2 m west"), the last correction first ("circles, no, figure eight - no,
    just circles" is "just circles"); as it was where a correction swaps nothing said before."""
    for _ in range(_SLIPS):
        mended = _last_slip(text)
        if mended == text:
            break
        text = mended
    return text


def _last_slip(text: str) -> str:
    """`text` with its last correction that corrects something applied; as it was when none does."""
    for said in reversed(list(_TAKEN_BACK.finditer(text))):
        before, after = text[: said.start()], text[said.end() :]
        stop = re.search(r"\s+(?:-|--|\u2013|\u2014)\s+|,\s*|\.\s+|\u2014|\u2013", after)
        fix, rest = (after[: stop.start()], after[stop.end() :]) if stop else (after, "")
        fix = fix.strip().rstrip(".!")
        if not before.strip() or not fix or fix.lower() in _NOT_CORRECTIONS:
            continue  # "in front of the ego car, I mean, sorry.": the correction came first
        if rest.strip(" .!").lower().startswith(fix.lower()):
            rest = ""  # "on. On.", "four. Four cones.": the correction said again
        cut, skip, aligned = _slipped(before, fix, broken=said.group(0).strip()[:1] in ",;-.\u2013\u2014")
        if cut < 0:
            return text
        word = re.match(r"[\w.]+", before[cut:])
        kept = ""
        if " " not in fix and word and any(re.fullmatch(kind, fix.lower()) for kind in _SWAPPED_KINDS):
            kept = before[cut + word.end() :]  # "three cones by the sign - sorry, four": that word swapped, the rest kept
        elif aligned:  # "a stop sigh near the crossing? Sorry, stop sign": as many words replaced as the correction has
            replaced = re.match(rf"\s*(?:\S+\s*){{{len(fix[skip:].split())}}}", before[cut:])
            kept = before[cut + replaced.end() :] if replaced else ""
            kept = "" if _TAKEN_BACK.search(before[cut:]) else kept  # what follows was itself taken back
            fix = fix[skip:]
        return " ".join(p for p in (before[:cut].rstrip(), fix, kept.strip(), rest.strip()) if p)
    return text


def _slipped(before: str, fix: str, broken: bool) -> tuple[int, int, bool]:
    """Where in `before` the words `fix` replaces begin, where in `fix` the replacement does, and
    whether the two were aligned on a word both say; (-1, 0, False) when it replaces nothing said.
    A thing said bare is replaced only where the speaker `broken` off with a mark ("add cones, no,
    barriers", never "I'm sorry to ask")."""
    head = re.sub(r"^(?:the|a|an)\s+", "", fix, flags=re.IGNORECASE).split(" ", 1)[0].lower()
    for kind in _SWAPPED_KINDS:  # a word of the same kind: the last one said
        slipped = list(re.finditer(rf"\b(?:{kind})\b", before, re.IGNORECASE))
        if re.fullmatch(kind, head) and slipped:
            cut = slipped[-1].start()
            more = re.search(r"\banother\s+$", before[:cut], re.IGNORECASE)  # "another one - no, two more"
            return (more.start() if more and re.search(r"\bmore\b", fix, re.IGNORECASE) else cut), 0, False
    low = before.lower()
    word = next((w for w in re.finditer(r"[a-z]+", fix.lower()) if w.group(0) not in _UNPLACED), None)
    found = [m.start() for m in re.finditer(rf"\b{word.group(0)}\b", low)] if word else []
    if word and found:  # the correction's first word said before: from where it was said
        return found[-1], word.start(), True
    last = re.search(r"\b([a-z]+)\W*$", low)
    if last and any(re.fullmatch(kind, last.group(1)) for kind in _SWAPPED_KINDS):
        return last.start(1), 0, False  # "in blue - sorry, tartan": the word just said
    if commands(fix.lower()) or _RESTART.match(fix.lower()):  # a request of its own: it replaces the last clause
        bounds = [m.end() for m in re.finditer(r"[.;!?,\u2014\u2013]\s*", before)]
        return (bounds[-1] if bounds else 0), 0, False
    thing = list(re.finditer(r"\b(?:(?:the|a|an)\s+[\w-]+(?:\s+[\w-]+)?|[a-z]+\s+\d+)(?:\s+(?:from|to|and|with|by))?\s*$",
                             before, re.IGNORECASE))  # "the bench", "bench 1 from"
    if thing:
        return thing[-1].start(), 0, False
    several = len(re.findall(r"[a-z]+", low)) > 1  # "add cones, no, barriers"; never "actually, make that five"
    return (last.start(1), 0, False) if last and broken and several else (-1, 0, False)


def without_reason_first(text: str) -> str:
    """`text` without a reason said first and followed by ", so" and what to do ("my learner needs
    practice, so have the ego brake"); when what follows points back into it ("..., so put bikes at
    its entrance"), the reason stays as the context of a colon."""
    first = _REASON_FIRST.match(text)
    if first is not None and not _POINTS_BACK.search(text[first.end() :]):
        return text[first.end() :]
    if first is not None:
        return text[: first.start() + text[: first.end()].rindex(",")] + ": " + text[first.end() :]
    return text


# A whole sentence that remembers ("Back home we'd tie the horse to a post.", "In my day the bin stood ...").
_MEMORY = re.compile(rf"(?:^|(?<=[.!?;]))\s*(?:\w+,?\s+){{0,2}}?{REMINISCED.pattern}[^.!?;]*[.!?;]+", re.IGNORECASE)


def without_memories(text: str) -> str:
    """`text` without its sentences that tell a memory, when something else is left."""
    kept = _MEMORY.sub(" ", text)
    return kept.strip() if kept.strip() else text


def without_reason(text: str) -> str:
    """`text` without the clauses that only say why ("so buses can pass", "to test the wipers,
    so give me rain") or what is not meant (", not the ego"), without labels pasted with it
    ("JIRA-412:"), and with a layout's heading read as words ("Ring: 6x cones" is a ring of 6x
    cones)."""
    text = _STEPS.sub("", _EXPECTED.sub("", _TAG.sub("", _CLEFT.sub("I want ", _ticket_outcome(without_slip(text))))))
    if (nominal := _NOMINAL_EDIT.match(text)) is not None:
        text = _ASKED_FOR.sub("", _NOMINAL[nominal.group(1).lower()] + text[nominal.end() :])
    text = without_contrast(_LAYOUT_HEADING.sub(r"\1 of", _LABEL.sub(" ", text))).strip()
    text = without_reason_first(without_memories(text))
    because = _BECAUSE_FIRST.match(text)
    if because is not None and not _POINTS_BACK.search(text[because.end() :]):
        text = text[because.end() :]
    later = _BECAUSE.search(text)
    if later is not None and len(text[: later.start()].split()) >= 2:  # "since when ..." asks
        text = _BECAUSE.sub("", text)
    return _AUDIENCE.sub(r"\1", _REASON.sub("", text))


# Who a thing is shown or pointed out to ("anything worth showing the kids near the fountain?"): no thing asked about.
_AUDIENCE = re.compile(r"\b(show(?:s|ing)?|point(?:s|ing)? out to|tell(?:s|ing)?)\s+(?:the|our|my|his|her|their|some)\s+"
                       r"(?:kids|children|visitors|guests|people|group|students|tourists|class|folks|passengers|team|crowd)\b")


# The person saying the scene must stay as it is ("no edits", "don't touch anything", "just
# checking"): whatever the sentence's mood, it asks for information.
_READ_ONLY = re.compile(r"\b(?:no (?:edits?|changes|alterations?|modifications?)|make no (?:changes|alterations?|edits?)|(?:don'?t|do not|dont) (?:touch|change|edit|modify|alter) "
                        r"(?:anything|a thing|the scene)(?! else)|without (?:touching|changing) anything(?! else)"
                        r"|just (?:checking|looking|asking|curious)|read[- ]only)\b")


# An amount of something offered with a question mark ("bit of drizzle?", "some more cones?",
# "a touch of fog, maybe?"): a suggestion, as "how about ..." is, not a question.
# A wish put as a question, hedged or bare ("bit of drizzle?", "maybe a couple of trees by the
# library?", "if there's room, a bike or two outside it?"): a suggestion of something to have.
_SUGGESTED = re.compile(r"^(?:(?:maybe|perhaps|possibly|how about|if there'?s (?:room|space)|if (?:possible|you can)|ooh|oh)[,\s]+)*"
                        r"(?:(?:a |an )?(?:bit|spot|touch|dash|hint|little|lot|drop|couple|few|pair) of|some|more|a little|a bit"
                        r"|(?:a|an|one|two|three|four|five|\d+) (?!(?:question|quick question|thing)\b)(?=[a-z]))\b")


# A hedge that opens a clause after what was said of the scene, and the suggestion after it.
_HEDGE_AFTER = re.compile(r"(?:[,;:\u2013\u2014]|\s-)\s*((?:maybe|perhaps|possibly|how about)\b.*)$")


def _suggested_after(low: str) -> bool:
    """Whether a statement ends in a hedged suggestion ("the bus stop looks lonely - maybe a couple of folks waiting
    there?"), not in a question ("which car is nearest, maybe a sedan?")."""
    hedged = _HEDGE_AFTER.search(low)
    return hedged is not None and not _QUESTION_START.search(low) and _SUGGESTED.match(low[hedged.start(1) :]) is not None


# A request to take back the last change or bring it back, said in words rather than as the
# `undo` command ("oops, undo that", "revert the last edit", "scratch that", "redo please"): the
# whole request, fillers aside. A request that names what to change back ("undo the red paint")
# is an edit like any other and is not read here.
_FILLERS = r"(?:(?:oops|whoops|oh no|uh oh|no|nah|hmm+|actually|sorry|ok(?:ay)?|please|pls|just|can you|could you|would you)[,!.\s]+)*"
_LAST = r"(?:\s+(?:that|it|this|the last (?:change|edit|step|one|thing|request)|my last (?:change|edit|request)|what you (?:just )?did))"
_TRAILER = r"(?:[\s,]+(?:please|pls|thanks|thank you|again))*\s*[.!?]*\s*$"
_UNDO = re.compile("^" + _FILLERS + r"(?:undo" + _LAST + r"?|revert" + _LAST + r"?|roll(?:" + _LAST + r")? back" + _LAST + r"?"
                   r"|take (?:that|it) back|scratch that|cancel (?:that|the last (?:change|edit))|go back (?:one|a) step"
                   r"|(?:put|set|change) (?:it|that|everything) back (?:to )?(?:how|the way|as) it was)" + _TRAILER)
_REDO = re.compile("^" + _FILLERS + r"(?:redo" + _LAST + r"?|undo the undo)" + _TRAILER)


def history_request(low: str) -> str | None:
    """"undo" or "redo" when the (lower-case) words ask only for that, else None."""
    text = low.strip()
    if _UNDO.match(text):
        return "undo"
    if _REDO.match(text):
        return "redo"
    return None


def wrapped_request(low: str) -> bool:
    """Whether the (lower-case) words wrap a request for a change in a question ("is it possible
    to make the SUV drive ...?")."""
    return bool(_WRAPPED.search(low))


# A sentence that opens with a command ("umm remove the bus, I think there's one somewhere?"): a
# command, whatever question mark ends it.
_IMPERATIVE = re.compile(r"^(?:(?:um+|uh+|erm|ok(?:ay)?|so|hey|right|now|then|and|also|please|pls|just)[,\s]+)*"
                         r"(?:add|put|place|remove|delete|move|get rid of|take|paint|park|spawn|create|shift|rotate|clear|empty|drop"
                         r"|close|block|lose|swap|replace|line|surround|fence|set|turn|make|change|bring|give (?:the|that|this|our|it|them)"
                         r"|do (?:the same|that|this|it)(?: again)?)\b(?!-)")


# A speaker taking back a whole request in the same breath and saying another ("put the bench by
# the fountain... no wait, scrap that, just turn it round"), and a number corrected with a bare "no"
# ("two, no, three cones"). A word taken back ("3 m north, no wait, south") is without_slip's.
_RETRACTED = re.compile(r"(?:\.{2,}|\u2026|[,;:.!?])\s*(?:(?:no|oh|um+|uh+|hmm+|sorry)[,.!]*\s+)*(?:(?:wait|hang on|hold on)[,.!]*\s+)?"
                        r"(?:scrap|scratch|forget|cancel|ignore|strike)\s+(?:that|this|it)\b[,.;:!?\s]*")
_SAID_NUMBER = r"(?:\d+|one|two|three|four|five|six|seven|eight|nine|ten|eleven|twelve)"
_NUMBER_CORRECTED = re.compile(rf"\b{_SAID_NUMBER},?\s+no,?\s+(?={_SAID_NUMBER}\b)", re.IGNORECASE)
# Fewer words than this after "scrap that" correct a word, not the request.
_REQUEST_WORDS = 3


def taken_back(text: str) -> tuple[str, str]:
    """The request as meant and the request the speaker took back in it: what follows the last
    "scrap that" when it is a request of its own, and the second of a number corrected with "no";
    what was taken back is "" when nothing was."""
    text = _NUMBER_CORRECTED.sub("", text)
    last = next(reversed(list(_RETRACTED.finditer(text))), None)
    if last is None or last.start() == 0 or len(re.findall(r"[a-z]+", text[last.end() :], re.IGNORECASE)) < _REQUEST_WORDS:
        return text, ""
    return text[last.end() :], text[: last.start()]


# The thing a question asks after: "how many X", "where is the X", "is there a X", "the nearest X",
# "any X about?". A word this world does not know there is a thing it cannot answer about.
# Words for a kind of place, not a thing: "the nearest landmark", "which buildings".
PLACE_KIND = re.compile(r"\b(?:landmarks?|places?|buildings?|entrances?|locations?|spots?)\b")
ASKED_ABOUT = re.compile(r"(?:\b(?:how many|where (?:is|are|do|does|did|can|could|will|would|should)(?: the| a| an| my| our| any)?"
                          r"|(?:is|are) there(?: any| an?| some)?|nearest|closest)|^\s*any) "
                          # "how many kilograms is it?": a measure asked, no thing
                          r"(?!(?:kilo\w*|tonnes?|tons?|pounds?|grams?|metres?|meters?|feet|seconds?|minutes?|hours?|degrees?|percent|times)\b)"
                          r"([a-z]{3,})\b")
# The words right before the kind a question asks for by "which" ("my students wait at the stop: which bench is
# closest to them?": a bench, the students only its setting).
WHICH_KIND = re.compile(r"\b(?:which|what)\s+(?:[a-z]+\s+)?$")


def commands(low: str) -> bool:
    """Whether the (lower-case) clause opens with a command ("umm remove the bus", "do the same")."""
    return _IMPERATIVE.match(low.strip()) is not None


# Asking to be given a thing, the subject left out or not: "can have one bus somewhere?", "could we get two cones?".
_HAVE_ONE = re.compile(r"\s*(?:can|could|may)\s+(?:i\s+|we\s+)?(?:have|get)\s+(?:a|an|one|some|two|three|four|five|\d+|more|another)\b"
                       r"(?!\s+(?:look|go|think|word|minute|sec|second|moment|chat|idea|sense|feel|view|list|count)\b)")


# A layout offered with a question mark: "people in a circle round the fountain?", "cones in a row by the gate?".
_LAYOUT_OFFERED = re.compile(r"\bin an? (?:circle|ring|row|line|grid|queue|semicircle|square)\b")


def _setting_offered(low: str) -> bool:
    """A few words with a question mark that name a weather or a time of day, or a layout, and ask
    nothing ("sunset vibes?", "heavy rain?", "people in a circle round the fountain?"): offered as a
    change, not asked about."""
    words = re.findall(r"[a-z']+", low)
    if low.rstrip().endswith("?") and len(words) <= 10 and _LAYOUT_OFFERED.search(low) and not _QUESTION_START.search(low) \
            and not _INFO.search(low):
        return True  # "people in a circle round the fountain?": a layout offered, not asked about
    if not low.rstrip().endswith("?") or not 0 < len(words) <= 4 or _QUESTION_START.search(low) or _INFO.search(low) \
            or re.search(r"\b(?:or not|or no|or nah|yet|still|out|outside)\b", low):
        return False  # "rain or not?", "dark yet?", "foggy out?": asked about
    return _settings_offered().search(" ".join(words)) is not None


@cache
def _settings_offered() -> re.Pattern[str]:
    """Weather and time words that name a thing offered ("fog", "heavy rain", "sunset"); a state
    said ("foggy?", "raining?") asks instead. The planners' words, imported here so intent stays importable alone."""
    from drivetwin.orchestrator.planning.rules import lexicon as lx

    words = {w for kind in lx.WEATHER_WORDS.values() for w in kind} | {w for names, _ in lx.TIME_PRESETS for w in names}
    offered = sorted(w for w in words if w not in ("dark", "day", "sun", "clear weather") and not w.endswith(("y", "ing")))
    return re.compile(rf"\b(?:{'|'.join(re.escape(w) for w in offered)})\b")


# A thing in the scene asked, politely, to do something ("can the SUV do a few laps?", "could one of
# the cars wait outside the library?", "could it potter about a bit?"): a request, whatever its verb,
# unless the words after it ask what it is able to do or perceive, or how things are now ("could the
# bus fit in lot B?", "could the lamps be on at the moment, or is it day?").
_THING_ASKED = re.compile(r"(?:^|[.!;?,:]\s*)(?:can|could) (?:(?:one|some|any|two|both|each) of )?"
                          r"(?:(?:the|that|this|these|those|our|my|its) [a-z_0-9]+|it|they|(?:[a-z]+_\d+))\b(?P<rest>(?: [a-z']+){1,4}[^.;!?]*)")
_ABILITY = re.compile(r"\b(?:see|fit|reach|hear|tell|know|weigh|hold|carry|cope|handle|exist|still|really|actually|ever|even"
                      r"|possibly|already|physically|legally|be seen|mean|happen|cause|hit|crash|collide|block|get hit"
                      r"|at the moment|currently|right now|yet|or (?:is|are|not|no))\b")  # "..., or is it still daytime?"
# A wish stated as what would be good ("something green by the hall would be nice").
_WOULD_BE_NICE = re.compile(r"\b(?:would|'d) (?:be|look) (?:(?:really|very|so|rather|quite) )?(?:nice|lovely|good|great|better|nicer|fun|cool|helpful|useful|ideal)\b")


def _thing_asked(low: str) -> bool:
    """Whether a thing in the scene is asked to do something (see _THING_ASKED), or a wish is stated."""
    for said in _THING_ASKED.finditer(low):
        if _ABILITY.search(said.group("rest")) is None:
            return True
    return _WOULD_BE_NICE.search(low) is not None and _QUESTION_START.search(low) is None  # "what would be nice here?" asks


# Asking to see the scene some other way: "show me how the street looks at eleven at night", "what
# would it look like in the fog?". With a weather or a time named after it, a change to look at.
_SHOWN = re.compile(r"\b(?:show me|let me see|let'?s see|i (?:want|would like|'d like) to see|(?:can|could) (?:i|we) see"
                    r"|what (?:would|will|does) (?:it|\w+(?: \w+)?) look like|how (?:would|will|does) (?:it|\w+(?: \w+)?) look)\b(?P<rest>[^.;!?]*)")


def setting_shown(low: str) -> bool:
    """Whether the words ask to see the scene in a weather or at a time they name (see _SHOWN)."""
    from drivetwin.orchestrator.planning.rules.clock import clock_time  # the planners' reader, as in _settings_offered

    return any(_settings_offered().search(said.group("rest")) or clock_time(said.group("rest")) is not None
               for said in _SHOWN.finditer(low))


# A tag question ending a statement: "..., right?", "..., isn't it?", "..., yeah?" (not "ok?", which asks leave).
TAG_QUESTION = re.compile(r",\s*(?:right|yeah|yes|correct|true|no|is(?:n'?t| not)? (?:it|there|that)|are(?:n'?t| not)? (?:they|there))\s*\?+\s*$")


# Words that only name the state of the scene: a request of nothing else asks what it is.
_STATUS_WORDS = frozenset({"current", "present", "conditions", "weather", "time", "clock", "lighting", "status", "and", "the", "of",
                           "day", "now", "right", "please", "pls", "thanks", "so", "ok", "okay", "what's", "whats", "plus"})


def asks(low: str) -> bool:
    """Whether the (lower-case) words ask for information rather than for a change."""
    if setting_shown(low):
        return False  # "show me the campus at dawn": the scene set so, to be seen
    if set(re.findall(r"[a-z']+", low)) <= _STATUS_WORDS and re.search(r"\b(?:conditions|weather|clock|time|lighting|status)\b", low) \
            and not re.search(r"\d", low):  # "time 18:15" gives the value: a setting
        return True  # "Current conditions, please: weather and clock.": no change and no value, so what they are
    if TAG_QUESTION.search(low) and not commands(low):
        return True  # "the SUV is parked, yeah?": whether what was said is so
    polite = bool(_POLITE.search(low) or _SUGGESTED.match(low.strip()) or _suggested_after(low) or _WRAPPED.search(low)
                  or _IMPERATIVE.match(low.strip()) or _setting_offered(low) or _HAVE_ONE.match(low) is not None or _thing_asked(low))
    info = _INFO.search(_AMOUNT_CHANGED.sub(" ", low))  # "double the number of benches" asks for no count
    return bool(info or _LOOKUP.match(low) or _READ_ONLY.search(low)) or (
        not polite and (bool(_QUESTION_START.search(low)) or low.rstrip().endswith("?")
                        or bool(re.search(r"\?\s+(?:just |only )?(?:return|give|list|report|show)\b", low))))


__all__ = [
    "ADD_WORDS",
    "ASKED_ABOUT",
    "BARE_STATE",
    "FEWER_WORDS",
    "HOW_THINGS_GO",
    "KEEP_SOME",
    "LIVELIER",
    "NONE_THERE",
    "PLACE_KIND",
    "QUIETER",
    "REMINISCED",
    "REMOVE_WORDS",
    "REPORTED",
    "SAID_MISSING",
    "TAG_QUESTION",
    "WHAT_IF",
    "WHICH_KIND",
    "asks",
    "commands",
    "excepted",
    "history_request",
    "setting_shown",
    "taken_back",
    "without_contrast",
    "without_memories",
    "without_reason",
    "without_reason_first",
    "without_salutations",
    "wrapped_request",
]

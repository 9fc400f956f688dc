; blind25 p04: IPC-style blocks with spots, untyped, :strips only (static
; `block`/`spot` predicates; `clear` deleted while held, so nothing is
; stacked on itself).
(define (domain pedestal-blocks)
  (:requirements :strips)
  (:predicates (block ?b) (spot ?s)
               (at ?b ?s) (on ?b ?c) (clear ?b) (holding ?b) (handempty))

  (:action pick
    :parameters (?b ?s)
    :precondition (and (block ?b) (spot ?s) (at ?b ?s) (clear ?b) (handempty))
    :effect (and (holding ?b) (not (at ?b ?s)) (not (clear ?b))
                 (not (handempty))))

  (:action place
    :parameters (?b ?s)
    :precondition (and (block ?b) (spot ?s) (holding ?b))
    :effect (and (at ?b ?s) (clear ?b) (handempty) (not (holding ?b))))

  (:action unstack
    :parameters (?b ?c)
    :precondition (and (block ?b) (block ?c) (on ?b ?c) (clear ?b) (handempty))
    :effect (and (holding ?b) (clear ?c) (not (on ?b ?c)) (not (clear ?b))
                 (not (handempty))))

  (:action stack
    :parameters (?b ?c)
    :precondition (and (block ?b) (block ?c) (holding ?b) (clear ?c))
    :effect (and (on ?b ?c) (clear ?b) (not (clear ?c)) (handempty)
                 (not (holding ?b)))))

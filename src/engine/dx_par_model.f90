!> A rank's sub-model for the MPI engine (first piece of step 5; docs/history.md): its element
!> blocks are the pieces of the serial blocks it holds (serial block order, serial position
!> order), so the unchanged element kernels visit every interior node's contributions in the
!> serial order. A corner whose node is shared gets its own "slot" node (index nloc + slot)
!> in the block connectivity: the kernel's scatter then writes that single contribution into
!> f(:, nloc + slot) (0 - c, exactly -c), and par_shared_sum adds all ranks' slots of a node
!> in serial key order (scatter_keys: the serial loop `do k = 1, nen; do i = 1, nel` per
!> block) - bit for bit the serial sum, with no change to the kernels. The nodal mass is
!> scattered element-major (`do i; do k` in init_state), so it has its own keys and plan;
!> so are the shell kernel's forces and moments (family_t%scatter_em), and the rotary
!> inertia (par_exchange_mass on it). Moments use the force plan.
!> Follows the fixed-order idea of OpenRadioss /PARITH/ON and ParaDyn's single shared-node
!> exchange per cycle (LLNL Engineering Thrust Area Report FY97, article 4 of shared/seed).
module dx_par_model
   use dx_kinds, only: wp, nv_chunk
   use dx_model, only: model_t, elem_block_t, MAX_NEN, family_t, element_family
   use dx_partition, only: rank_part_t
   use dx_rank_submodel, only: rank_local_node, rank_records_verify
   use dx_strings, only: str
   use dx_par_plan, only: shared_sum_t, par_shared_setup, par_shared_sum, par_shared_post, &
                          par_shared_finish, par_shared_drop
   implicit none
   private
   public :: par_model_t, par_model_build, par_fill_slots, par_exchange_forces, &
             par_exchange_mass, par_model_from_file, par_model_fill_state, par_model_verify, &
             par_exchange_post, par_exchange_drop

   type :: par_model_t
      integer :: nloc = 0                       !< the rank's nodes (local 1..nloc)
      integer :: nslot = 0                      !< slot nodes nloc+1..nloc+nslot
      integer :: nshared = 0
      integer, allocatable :: node_global(:)    !< (nloc) global node index
      integer, allocatable :: slot_node(:)      !< (nslot) local node of each slot
      integer, allocatable :: shared_local(:)   !< (nshared) local node of each shared node
      type(elem_block_t), allocatable :: blocks(:)   !< pieces of the serial blocks
      integer, allocatable :: block_serial(:)   !< serial block of each piece
      type(shared_sum_t) :: force_plan, mass_plan
   end type par_model_t

contains

   !> Build rank rp%rank's sub-model from the (serial, built) model and its rank file's
   !> partition: the cut (the replicated path; dynx-part --verify compares it with
   !> par_model_from_file).
   subroutine par_model_build(model, rp, pm)
      type(model_t), intent(in) :: model
      type(rank_part_t), intent(in) :: rp
      type(par_model_t), intent(out) :: pm
      integer, allocatable :: c_node(:), c_fkey(:), c_mkey(:), nbr_snode(:)
      call cut_layout(model, rp, pm, c_node, c_fkey, c_mkey, nbr_snode, .true.)
      call par_shared_setup(pm%force_plan, pm%nshared, rp%nbr, rp%nbr_ptr, nbr_snode, &
                            c_node, c_fkey)
      call par_shared_setup(pm%mass_plan, pm%nshared, rp%nbr, rp%nbr_ptr, nbr_snode, &
                            c_node, c_mkey)
   end subroutine par_model_build

   !> Rank rp%rank's sub-model from its rank file alone (format 2: rp's sub-model arrays):
   !> the pieces' connectivity with slot nodes, the slot and shared-node maps and the two
   !> fixed-order sum plans, with the keys par_model_build forms from the global blocks.
   !> Every array is sized by the rank's nodes and elements. The element state (sig, hv,
   !> vol0, ...; nip, nhv) is not set: par_model_fill_state (stage 1).
   subroutine par_model_from_file(rp, pm)
      type(rank_part_t), intent(in) :: rp
      type(par_model_t), intent(out) :: pm
      integer, allocatable :: c_node(:), c_fkey(:), c_mkey(:), nbr_snode(:)
      call file_layout(rp, pm, c_node, c_fkey, c_mkey, nbr_snode)
      call par_shared_setup(pm%force_plan, pm%nshared, rp%nbr, rp%nbr_ptr, nbr_snode, &
                            c_node, c_fkey)
      call par_shared_setup(pm%mass_plan, pm%nshared, rp%nbr, rp%nbr_ptr, nbr_snode, &
                            c_node, c_mkey)
   end subroutine par_model_from_file

   !> The cut of par_model_build without the plans' exchange: the sub-model and the inputs
   !> of the two plans (c_node, c_fkey, c_mkey per slot; nbr_snode).
   subroutine cut_layout(model, rp, pm, c_node, c_fkey, c_mkey, nbr_snode, state)
      type(model_t), intent(in) :: model
      type(rank_part_t), intent(in) :: rp
      logical, intent(in) :: state
      type(par_model_t), intent(out) :: pm
      integer, allocatable, intent(out) :: c_node(:), c_fkey(:), c_mkey(:), nbr_snode(:)
      integer, allocatable :: loc(:), snum(:), piece(:)
      logical, allocatable :: here(:), shared(:)
      type(family_t) :: fam
      integer :: i, j, k, b, nb, n, slot, s
      pm%nloc = size(rp%nodes)
      pm%node_global = rp%nodes
      allocate(loc(model%nn), snum(model%nn), here(model%ne), shared(model%nn))
      loc = 0
      do i = 1, pm%nloc
         loc(rp%nodes(i)) = i
      end do
      here = .false.
      here(rp%elements) = .true.
      shared = .false.
      shared(rp%nbr_nodes) = .true.
      snum = 0
      s = 0
      do i = 1, pm%nloc
         if (shared(rp%nodes(i))) then
            s = s + 1
            snum(rp%nodes(i)) = s
         end if
      end do
      pm%nshared = s
      allocate(pm%shared_local(s))
      do i = 1, pm%nloc
         if (snum(rp%nodes(i)) > 0) pm%shared_local(snum(rp%nodes(i))) = i
      end do
      ! pieces of the serial blocks, in serial order
      nb = 0
      do b = 1, size(model%blocks)
         if (any(here(model%blocks(b)%elem))) nb = nb + 1
      end do
      allocate(pm%blocks(nb), pm%block_serial(nb))
      allocate(c_node(MAX_NEN*size(rp%elements)), c_fkey(MAX_NEN*size(rp%elements)), &
               c_mkey(MAX_NEN*size(rp%elements)), pm%slot_node(MAX_NEN*size(rp%elements)))
      nb = 0
      slot = 0
      do b = 1, size(model%blocks)
         associate (sb => model%blocks(b))
            piece = pack([(i, i = 1, sb%nel)], here(sb%elem))
            if (size(piece) == 0) cycle
            nb = nb + 1
            pm%block_serial(nb) = b
            fam = element_family(sb%etype)
            associate (pb => pm%blocks(nb))
               pb%ipart = sb%ipart
               pb%etype = sb%etype
               pb%nel = size(piece)
               pb%nip = sb%nip
               pb%nhv = sb%nhv
               pb%elem = sb%elem(piece)
               if (state) then   ! (the verifier compares the topology only)
                  pb%sig = sb%sig(piece, :, :)
                  pb%hv = sb%hv(piece, :, :)
                  pb%vol0 = sb%vol0(piece)
                  pb%relvol = sb%relvol(piece)
                  pb%eint = sb%eint(piece)
                  pb%ehg = sb%ehg(piece)
                  pb%failed = sb%failed(piece)
                  ! the family state (a restart reads it): every slot of the serial block
                  if (allocated(sb%es)) pb%es = sb%es(piece, :)
                  pb%esc = sb%esc; pb%esn = sb%esn
               end if
               allocate(pb%conn(size(sb%conn, 1), pb%nel))
               ! slots numbered corner-major as the force scatter visits them
               do k = 1, size(sb%conn, 1)
                  do j = 1, pb%nel
                     n = sb%conn(k, piece(j))
                     if (snum(n) > 0) then
                        slot = slot + 1
                        pb%conn(k, j) = pm%nloc + slot
                        pm%slot_node(slot) = loc(n)
                        c_node(slot) = snum(n)
                        ! force: the serial scatter order (dx_partition scatter_keys),
                        ! formed here for the rank's corners only
                        c_fkey(slot) = ((b - 1)*MAX_NEN + k - 1)*nv_chunk + piece(j)
                        ! mass: element-major serial order (block, position, corner)
                        c_mkey(slot) = ((b - 1)*nv_chunk + piece(j) - 1)*MAX_NEN + k
                        ! a family that scatters element-major (shells: forces and
                        ! moments) sums in that order; both keys span the same range
                        ! per block, so blocks of both kinds interleave in serial order
                        if (fam%scatter_em) c_fkey(slot) = c_mkey(slot)
                     else
                        pb%conn(k, j) = loc(n)
                     end if
                  end do
               end do
            end associate
         end associate
      end do
      pm%nslot = slot
      pm%slot_node = pm%slot_node(1:slot)
      nbr_snode = snum(rp%nbr_nodes)
      c_node = c_node(1:slot)
      c_fkey = c_fkey(1:slot)
      c_mkey = c_mkey(1:slot)
   end subroutine cut_layout

   !> file_layout: cut_layout's result from the rank file's sub-model alone (rank-local
   !> arrays only: the global node of a corner is found in the ascending rp%nodes).
   subroutine file_layout(rp, pm, c_node, c_fkey, c_mkey, nbr_snode)
      type(rank_part_t), intent(in) :: rp
      type(par_model_t), intent(out) :: pm
      integer, allocatable, intent(out) :: c_node(:), c_fkey(:), c_mkey(:), nbr_snode(:)
      integer, allocatable :: snum(:)
      type(family_t) :: fam
      integer :: i, j, k, b, p, n, nen, slot, s, ne, j0, ln
      pm%nloc = size(rp%nodes)
      pm%node_global = rp%nodes
      ! snum(i): shared-node number of local node i (0: not shared), ascending local order
      allocate(snum(pm%nloc), nbr_snode(size(rp%nbr_nodes)))
      snum = 0
      do i = 1, size(rp%nbr_nodes)
         nbr_snode(i) = rank_local_node(rp%nodes, rp%nbr_nodes(i))   ! local first
         snum(nbr_snode(i)) = 1
      end do
      s = 0
      do i = 1, pm%nloc
         if (snum(i) > 0) then
            s = s + 1
            snum(i) = s
         end if
      end do
      pm%nshared = s
      allocate(pm%shared_local(s))
      do i = 1, pm%nloc
         if (snum(i) > 0) pm%shared_local(snum(i)) = i
      end do
      nbr_snode = snum(nbr_snode)
      ne = size(rp%piece_elem)
      allocate(pm%blocks(size(rp%piece_ptr) - 1), pm%block_serial(size(rp%piece_ptr) - 1))
      allocate(c_node(MAX_NEN*ne), c_fkey(MAX_NEN*ne), c_mkey(MAX_NEN*ne), &
               pm%slot_node(MAX_NEN*ne))
      slot = 0
      do p = 1, size(pm%blocks)
         b = rp%pieces(1, p)
         pm%block_serial(p) = b
         fam = element_family(rp%pieces(3, p))
         nen = fam%nen
         j0 = rp%piece_ptr(p) - 1
         associate (pb => pm%blocks(p))
            pb%ipart = rp%pieces(2, p)
            pb%etype = rp%pieces(3, p)
            pb%nel = rp%piece_ptr(p + 1) - rp%piece_ptr(p)
            pb%elem = rp%piece_elem(j0 + 1:j0 + pb%nel)
            allocate(pb%conn(nen, pb%nel))
            do k = 1, nen           ! slots corner-major, as the force scatter visits them
               do j = 1, pb%nel
                  n = rp%piece_conn(k, j0 + j)
                  ln = rank_local_node(rp%nodes, n)
                  if (snum(ln) > 0) then
                     slot = slot + 1
                     pb%conn(k, j) = pm%nloc + slot
                     pm%slot_node(slot) = ln
                     c_node(slot) = snum(ln)
                     c_fkey(slot) = ((b - 1)*MAX_NEN + k - 1)*nv_chunk + rp%piece_pos(j0 + j)
                     c_mkey(slot) = ((b - 1)*nv_chunk + rp%piece_pos(j0 + j) - 1)*MAX_NEN + k
                     if (fam%scatter_em) c_fkey(slot) = c_mkey(slot)
                  else
                     pb%conn(k, j) = ln
                  end if
               end do
            end do
         end associate
      end do
      pm%nslot = slot
      pm%slot_node = pm%slot_node(1:slot)
      c_node = c_node(1:slot)
      c_fkey = c_fkey(1:slot)
      c_mkey = c_mkey(1:slot)
   end subroutine file_layout

   !> Stage 1: the element state of the file-built sub-model (nip, nhv, sig, hv, vol0,
   !> relvol, eint, ehg, failed, family state) from the built serial blocks of model, at the
   !> pieces' serial positions (what par_model_build copies).
   subroutine par_model_fill_state(pm, model, rp)
      type(par_model_t), intent(inout) :: pm
      type(model_t), intent(in) :: model
      type(rank_part_t), intent(in) :: rp
      integer :: p, j0
      integer, allocatable :: piece(:)
      do p = 1, size(pm%blocks)
         j0 = rp%piece_ptr(p) - 1
         associate (pb => pm%blocks(p), sb => model%blocks(pm%block_serial(p)))
            piece = rp%piece_pos(j0 + 1:j0 + pb%nel)
            pb%nip = sb%nip
            pb%nhv = sb%nhv
            pb%sig = sb%sig(piece, :, :)
            pb%hv = sb%hv(piece, :, :)
            pb%vol0 = sb%vol0(piece)
            pb%relvol = sb%relvol(piece)
            pb%eint = sb%eint(piece)
            pb%ehg = sb%ehg(piece)
            pb%failed = sb%failed(piece)
            if (allocated(sb%es)) pb%es = sb%es(piece, :)
            pb%esc = sb%esc; pb%esn = sb%esn
         end associate
      end do
   end subroutine par_model_fill_state

   !> dynx-part --verify: the sub-model built from the rank file (rp, read back) against the
   !> one cut from the global model for the same partition, bit for bit: the nodes, their
   !> initial coordinates, velocities and labels, the pieces (serial block, part, type,
   !> elements, connectivity with slots), the slot and shared maps and the keys and nodes
   !> of both fixed-order sums. msg: empty when equal, else the first difference.
   subroutine par_model_verify(model, rp, msg)
      type(model_t), intent(in) :: model
      type(rank_part_t), intent(in) :: rp
      character(:), allocatable, intent(out) :: msg
      type(par_model_t) :: a, b
      integer, allocatable :: an(:), af(:), am(:), as(:), bn(:), bf(:), bm(:), bs(:)
      integer :: p
      msg = ''
      if (.not. allocated(rp%piece_ptr)) then
         msg = 'no sub-model in the file'
         return
      end if
      if (.not. same_r(rp%x0, model%x0(:, rp%nodes))) msg = 'initial coordinates'
      if (.not. same_r(rp%v0, model%v0(:, rp%nodes))) msg = 'initial velocities'
      if (any(rp%node_label /= model%node_label(rp%nodes))) msg = 'node labels'
      if (len(msg) > 0) return
      call rank_records_verify(model, rp, msg)   ! SPCs, prescribed motions, nodal loads
      if (len(msg) > 0) return
      do p = 1, size(rp%piece_ptr) - 1      ! each element at its serial block and position
         associate (sb => model%blocks(rp%pieces(1, p)), &
                    j => rp%piece_pos(rp%piece_ptr(p):rp%piece_ptr(p + 1) - 1))
            if (any(j < 1 .or. j > sb%nel)) then
               msg = 'serial positions of piece '//str(p)
            else if (any(sb%elem(j) /= rp%piece_elem(rp%piece_ptr(p):rp%piece_ptr(p + 1) - 1))) &
               then
               msg = 'serial positions of piece '//str(p)
            end if
         end associate
         if (len(msg) > 0) return
      end do
      call cut_layout(model, rp, a, an, af, am, as, .false.)
      call file_layout(rp, b, bn, bf, bm, bs)
      if (a%nloc /= b%nloc .or. a%nslot /= b%nslot .or. a%nshared /= b%nshared) then
         msg = 'node, slot or shared-node counts'
      else if (any(a%node_global /= b%node_global) .or. any(a%slot_node /= b%slot_node) &
               .or. any(a%shared_local /= b%shared_local)) then
         msg = 'node, slot or shared-node maps'
      else if (size(a%blocks) /= size(b%blocks)) then
         msg = 'number of pieces'
      else if (any(a%block_serial /= b%block_serial)) then
         msg = 'serial blocks of the pieces'
      else if (any(an /= bn) .or. any(as /= bs)) then
         msg = 'shared-node numbers of the slots or neighbour lists'
      else if (any(af /= bf)) then
         msg = 'force-sum keys'
      else if (any(am /= bm)) then
         msg = 'mass-sum keys'
      end if
      if (len(msg) > 0) return
      do p = 1, size(a%blocks)
         associate (x => a%blocks(p), y => b%blocks(p))
            if (x%ipart /= y%ipart .or. x%etype /= y%etype .or. x%nel /= y%nel) then
               msg = 'part, type or size of piece '//str(p)
            else if (any(x%elem /= y%elem)) then
               msg = 'elements of piece '//str(p)
            else if (any(shape(x%conn) /= shape(y%conn))) then
               msg = 'connectivity shape of piece '//str(p)
            else if (any(x%conn /= y%conn)) then
               msg = 'connectivity of piece '//str(p)
            end if
         end associate
         if (len(msg) > 0) return
      end do
   contains
      logical function same_r(u, v)
         real(wp), intent(in) :: u(:, :), v(:, :)
         same_r = all(shape(u) == shape(v))
         if (same_r) same_r = all(transfer(u, [0]) == transfer(v, [0]))
      end function same_r
   end subroutine par_model_verify


   !> Copy the shared nodes' state (x, v: (3, nloc + nslot)) into their slot nodes.
   subroutine par_fill_slots(pm, a)
      type(par_model_t), intent(in) :: pm
      real(wp), intent(inout) :: a(:, :)
      integer :: i
      do i = 1, pm%nslot
         a(:, pm%nloc + i) = a(:, pm%slot_node(i))
      end do
   end subroutine par_fill_slots

   !> After the element pass into f (3, nloc + nslot), zeroed before it: the one exchange;
   !> f at the shared nodes becomes the serial sum of all ranks' contributions. When the
   !> slots' values were posted already (par_exchange_post) only the wait and the sums.
   subroutine par_exchange_forces(pm, f)
      type(par_model_t), intent(inout) :: pm
      real(wp), intent(inout) :: f(:, :)
      if (.not. pm%force_plan%posted) &
         call par_shared_post(pm%force_plan, f(:, pm%nloc + 1:pm%nloc + pm%nslot))
      call par_shared_finish(pm%force_plan, f, pm%shared_local)
   end subroutine par_exchange_forces

   !> The slots of f are final (right after the element pass): their values sent now, the
   !> sums formed by the next par_exchange_forces (or discarded by par_exchange_drop).
   subroutine par_exchange_post(pm, f)
      type(par_model_t), intent(inout) :: pm
      real(wp), intent(in) :: f(:, :)
      call par_shared_post(pm%force_plan, f(:, pm%nloc + 1:pm%nloc + pm%nslot))
   end subroutine par_exchange_post

   subroutine par_exchange_drop(pm)
      type(par_model_t), intent(inout) :: pm
      call par_shared_drop(pm%force_plan)
   end subroutine par_exchange_drop

   !> The same for the lumped mass (nloc + nslot), scattered element-major.
   subroutine par_exchange_mass(pm, mass)
      type(par_model_t), intent(inout) :: pm
      real(wp), intent(inout) :: mass(:)
      real(wp), allocatable :: res(:, :)
      allocate(res(1, pm%nshared))
      call par_shared_sum(pm%mass_plan, reshape(mass(pm%nloc + 1:pm%nloc + pm%nslot), &
                          [1, pm%nslot]), res)
      mass(pm%shared_local) = res(1, :)
   end subroutine par_exchange_mass
end module dx_par_model
